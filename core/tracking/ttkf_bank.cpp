#include "tracking/ttkf_bank.h"

#include <stdexcept>

namespace reckoner::track {

TtkfBank::TtkfBank(const TtkfConfig& config, std::size_t capacity)
    : ctx_(std::make_shared<const TtkfContext>(config)), capacity_(capacity) {
  if (capacity == 0) throw std::invalid_argument("TTKF bank: capacity must be positive");
  tracks_.reserve(capacity);
}

void TtkfBank::feedOwnShip(const OwnShipInput& own) {
  for (auto& t : tracks_) t.filter.feedOwnShip(own);
}

const TrackState* TtkfBank::processAssociated(int targetId, const GridPlot& plot,
                                              const OwnShipInput& lastOwn) {
  if (const auto it = byTarget_.find(targetId); it != byTarget_.end()) {
    TrackState& t = tracks_[it->second];
    t.lastRadar = t.filter.updateRadar(plot);
    t.radarUpdates += t.lastRadar.applied() ? 1 : 0;
    return &t;
  }
  if (tracks_.size() >= capacity_) {
    ++refused_;
    return nullptr;
  }
  byTarget_.emplace(targetId, tracks_.size());
  tracks_.push_back(TrackState{nextTrackId_++, targetId, Ttkf::initiate(ctx_, lastOwn, plot), 0, {}});
  return &tracks_.back();
}

void TtkfBank::predictAllTo(TimeUs t) {
  for (auto& tr : tracks_) tr.filter.predictTo(t);
}

}  // namespace reckoner::track
