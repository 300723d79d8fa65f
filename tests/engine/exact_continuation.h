// The engine tests' check of exact restart and thread independence: a
// world run, restored from its snapshot and run on past several rebuilds
// of the contact table gives the state of the uninterrupted run bit for
// bit, and the same world on two threads agrees.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>

#include "dem/world.h"

namespace dem::testing {

// Every history (shear springs, Mindlin reversal points, dashpot work,
// where each contact search ended, the fields that carry the particles)
// must carry over for the states to stay equal.
template <int Dim>
void expect_exact_continuation(WorldDefT<Dim> def, int before, int after, const char* what) {
  def.threads = 1;
  BasicWorld<Dim> original(def);
  def.threads = 2;
  BasicWorld<Dim> parallel(def);
  parallel.cycle(before + after);
  original.cycle(before);
  BasicWorld<Dim> restored(original.snapshot());
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  const std::uint64_t rebuilds_before = restored.profile().contact_rebuilds;
  original.cycle(after);
  restored.cycle(after);
  const EnergyBudget a = original.assembly_measures().energy, b = restored.assembly_measures().energy;
  const std::uint64_t rebuilds = restored.profile().contact_rebuilds - rebuilds_before;
  std::printf(
      "%s after %d + %d cycles (%llu table rebuilds): %zu contacts, original %016llx, restored %016llx, damping %.9e "
      "vs %.9e J\n",
      what, before, after, static_cast<unsigned long long>(rebuilds), original.contacts().size(),
      static_cast<unsigned long long>(original.state_hash()), static_cast<unsigned long long>(restored.state_hash()),
      a.contact_damping, b.contact_damping);
  EXPECT_GT(original.contacts().size(), 20u);
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  EXPECT_EQ(parallel.state_hash(), original.state_hash());
  EXPECT_EQ(a.contact_damping, b.contact_damping);
  EXPECT_EQ(a.friction, b.friction);
  EXPECT_GT(rebuilds, 0u);
}

}  // namespace dem::testing
