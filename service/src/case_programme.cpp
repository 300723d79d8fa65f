#include "dem/service/case_programme.h"

#include <algorithm>

namespace dem::service {

namespace {

template <int Dim>
bool resumable(const StageDefT<Dim>& stage, std::uint64_t stage_cycles, const WorldSession& session) {
  if (stage_cycles >= stage.cycles || stage_cycles % std::max<std::uint64_t>(stage.until.check_interval, 1) != 0) {
    return false;
  }
  return !(has_stop_condition(stage.until) && stage_cycles >= stage.until.min_cycles &&
           stop_conditions_hold(session.world<Dim>(), stage.until));
}

template <int Dim>
CaseProgramme one_stage_of(std::uint64_t cycles, const StopConditions& until) {
  StageDefT<Dim> stage;
  stage.cycles = cycles;
  stage.until = until;
  return CaseProgramme(std::vector<StageDefT<Dim>>{std::move(stage)});
}

}  // namespace

CaseProgramme CaseProgramme::one_stage(int dimension, std::uint64_t cycles, const StopConditions& until) {
  return dimension == 3 ? one_stage_of<3>(cycles, until) : one_stage_of<2>(cycles, until);
}

std::size_t CaseProgramme::stage_count() const {
  return std::visit([](const auto& stages) { return stages.size(); }, stages_);
}

const std::string& CaseProgramme::stage_name(std::size_t stage) const {
  return std::visit([&](const auto& stages) -> const std::string& { return stages.at(stage).name; }, stages_);
}

std::uint64_t CaseProgramme::stage_cycles(std::size_t stage) const {
  return std::visit([&](const auto& stages) { return stages.at(stage).cycles; }, stages_);
}

const StopConditions& CaseProgramme::stage_until(std::size_t stage) const {
  return std::visit([&](const auto& stages) -> const StopConditions& { return stages.at(stage).until; }, stages_);
}

StageStepper CaseProgramme::begin_stage(std::size_t stage, WorldSession& world, std::uint64_t done) const {
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
