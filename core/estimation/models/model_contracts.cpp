// Every measurement model in models/ satisfies the contract of the algebra it is passed to
// (model_concepts.h, docs/models.md): checked when the estimation library is built, so a model that
// drifts from its contract fails here, not at the first caller. The models of the sequential updates
// (est::update) are MeasurementModels; those a MeasurementStack carries also say where they are
// degenerate. (No model here is a ProcessModel: the DRKF and TTKF discretise their linear systems
// exactly and predict with predictLinear; ct:: and relpolar:: give the IMM and seed 001 plain functions.)
#include "estimation/model_concepts.h"
#include "estimation/models/drkf_ground_velocity.h"
#include "estimation/models/drkf_gyro.h"
#include "estimation/models/drkf_position_fix.h"
#include "estimation/models/drkf_radar_fix.h"
#include "estimation/models/drkf_speedlog.h"
#include "estimation/models/relative_polar.h"
#include "estimation/models/ttkf_radar.h"

namespace reckoner::est {

// The DRKF's stacked sensors (seed 000 eq. 7) and its radar fix (seed 004, a single update).
static_assert(StackableMeasurementModel<drkf::PositionFixModel, drkf::kStateDim>);
static_assert(StackableMeasurementModel<drkf::GroundVelocityModel, drkf::kStateDim>);
static_assert(StackableMeasurementModel<drkf::SpeedlogModel, drkf::kStateDim>);
static_assert(StackableMeasurementModel<drkf::GyroHeadingModel, drkf::kStateDim>);
static_assert(MeasurementModel<drkf::RadarFixModel, drkf::kStateDim>);
static_assert(MeasurementModel<drkf::RadarPositionModel, drkf::kStateDim>);

// The TTKF's radar plot and own-ship input (seed 000 eq. 9).
static_assert(StackableMeasurementModel<ttkf::RadarModel, ttkf::kStateDim>);
static_assert(StackableMeasurementModel<ttkf::OwnShipModel, ttkf::kStateDim>);

// Seed 001's bearing and range.
static_assert(MeasurementModel<relpolar::BearingRangeModel, relpolar::kStateDim>);

// A model of one state dimension does not pass for another's.
static_assert(!MeasurementModel<drkf::PositionFixModel, ttkf::kStateDim>);

}  // namespace reckoner::est
