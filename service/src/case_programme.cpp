#include "dem/service/case_programme.h"

#include <algorithm>

namespace dem::service {

namespace {

template <int Dim>
bool resumable(const StageDefT<Dim>& stage, std::uint64_t stage_cycles, const WorldSession& world) {
  if (stage_cycles >= stage.cycles || stage_cycles % std::max<std::uint64_t>(stage.until.check_interval, 1) != 0) {
    return false;
  }
  return !(has_stop_condition(stage.until) && stage_cycles >= stage.until.min_cycles &&
           stop_conditions_hold(*std::get<const BasicWorld<Dim>*>(world.view()), stage.until));
}

}  // namespace

std::size_t CaseProgramme::stage_count() const {
  return std::visit([](const auto& stages) { return stages.size(); }, stages_);
}

const std::string& CaseProgramme::stage_name(std::size_t stage) const {
  return std::visit([&](const auto& stages) -> const std::string& { return stages.at(stage).name; }, stages_);
}

std::uint64_t CaseProgramme::stage_cycles(std::size_t stage) const {
  return std::visit([&](const auto& stages) { return stages.at(stage).cycles; }, stages_);
}

std::unique_ptr<StageStepper> CaseProgramme::begin_stage(std::size_t stage, WorldSession& world,
                                                         std::uint64_t done) const {
  return std::visit(
      [&](const auto& stages) {
        // Resumed: the start actions are done and in the state.
        return world.begin_stage(done > 0 ? stage_remainder(stages.at(stage), done) : stages.at(stage));
      },
      stages_);
}

bool CaseProgramme::resumable_at(std::size_t stage, std::uint64_t stage_cycles, const WorldSession& world) const {
  return std::visit([&](const auto& stages) { return resumable(stages.at(stage), stage_cycles, world); }, stages_);
}

}  // namespace dem::service
