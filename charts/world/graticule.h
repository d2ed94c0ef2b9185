#pragma once
// The graticule of the world background: meridians and parallels at a round interval chosen from the
// view's scale, labelled at the screen's edges (the renderer draws them; this file chooses them).
#include <string>
#include <vector>

namespace reckoner::charts::world {

/// The round intervals, in arc-seconds: 1, 2, 5, 10, 15, 20 and 30 seconds and minutes, 1, 2, 5, 10, 15,
/// 20, 30 and 45 degrees.
const std::vector<int>& graticuleStepsSeconds();

/// The smallest round interval (graticuleStepsSeconds()) whose lines are at least `minSpacingPx`
/// apart on a screen where one degree of longitude is `pxPerDegree` pixels long; 45° at most.
/// In arc-seconds.
int graticuleStepSeconds(double pxPerDegree, double minSpacingPx = 110.0);

/// The multiples of `stepSeconds` in [loDeg, hiDeg], in degrees, at most `maxLines` of them (the
/// ones nearest the middle of the range when there would be more).
std::vector<double> graticuleValues(double loDeg, double hiDeg, int stepSeconds, int maxLines = 200);

}  // namespace reckoner::charts::world
