#pragma once
// Seed 004: the radar echoes matched to the chart's contours for a correction of position and heading
// (docs/radar_matching.md). Each echo i, seen at range r_i and relative bearing psi_i from own ship's
// pose at its own time (s_i, v_i: eq. 2, interpolated within the sweep), lies at
//   e_i = s_i + r_i (sin(psi_i + v_i), cos(psi_i + v_i)).
// Its nearest chart contour point k_i, within the rejection distance, gives the residual
// d_i = k_i - e_i. The corrections (ds_x, ds_y, dv) move every echo by ds + r_i (cos, -sin)(psi_i + v_i) dv
// (eq. 3 linearised in dv: eq. 4). Only d_i's component along the contour's normal n_i is information
// (the paper's fourth point), so each echo gives one row a_i' [ds; dv] = n_i' d_i with
//   a_i = (n_x, n_y, r_i (n_x cos - n_y sin)),
// weighted by the variance of the echo along n_i: the radar's errors in the echo's local frame
// (range sd along the beam, range times bearing sd across it, eq. 6) plus the contour's own sd (the
// object's reliability). Stacked (eq. 5) and solved by weighted least squares with an LDLT solve;
// the nearest points are found again after each solve until the correction settles.
#include <optional>
#include <vector>

#include "estimation/gaussian.h"
#include "radar/coastline.h"
#include "radar/radar_image.h"

namespace reckoner::radar {

struct MatchParams {
  double rejectDistanceM = 60.0;  ///< an echo farther than this from every contour is not the chart's
  double rangeSdM = 10.0;
  double bearingSdRad = 0.00872664625997;
  int maxIterations = 6;
  double settleM = 0.05;  ///< stop when the correction moves echoes less than this
  int minEchoes = 8;
  double outlierSigmas = 4.0;  ///< after the first solve, echoes this many sd off their contour are dropped
};

struct MatchResult {
  bool valid = false;                            ///< enough echoes and a positive definite normal matrix
  est::Vec<3> correction = est::Vec<3>::Zero();  ///< ds_x, ds_y (grid m), dv (rad): add to the pose
  est::Mat<3> covariance = est::Mat<3>::Zero();
  int echoes = 0, used = 0, rejected = 0, iterations = 0;
  std::vector<char> usedMask;                        ///< per echo: matched to the chart in the last iteration
  std::vector<est::Vec<2>> echoPoints, chartPoints;  ///< world positions of the matched echoes (after the
                                                     ///< correction) and their chart points
  std::vector<est::Vec<2>> rawEchoPoints;  ///< the same echoes placed from the pose before the correction
  double rmsNormalizedResidual = 0.0;      ///< of the used echoes after the correction (about 1 if honest)
  /// How the correction answers an error in the pose's motion. The echoes were placed with the pose's
  /// velocity and turn rate; if the ship's were larger by d = (dvx, dvy, domega), echo i (seen dt_i
  /// before the sweep's end) needed the correction at the end plus (-dt_i) d, and the least squares
  /// returns correction = (correction at the sweep's end) + S d, S = N^-1 sum_i w_i (-dt_i) a_i a_i'.
  /// A filter that knows its velocity and turn rate only roughly takes S into its measurement model
  /// (drkf_radar_fix.h) instead of treating the picture's end-of-sweep pose as independent of them.
  est::Mat<3> motionSensitivity = est::Mat<3>::Zero();
};

/// The echoes of one sweep against the contours, starting from `pose` (the filter's estimate).
MatchResult matchEchoes(const std::vector<EchoPoint>& echoes, const SweepPose& pose, const Coastline& coast,
                        const MatchParams& params);

}  // namespace reckoner::radar
