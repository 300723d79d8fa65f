// Particles close in space, close in memory. The order halves the assembly
// again and again (orthogonal recursive bisection), each time across its
// smallest section: a repeating axis counts twice, since cutting it cuts
// the period's seam too. Below 2,048 particles the cells of a grid
// one interaction range wide follow the Morton (Z) curve. Every contact
// then reads particles whose data share cache lines with its neighbours';
// a block of consecutive slots is a compact patch of the assembly
// (contact_blocks.h), and so is each thread's run of blocks: two threads
// share only the contacts across one cut (docs/PERFORMANCE.md, item 21).
// Ids never change; only slots move.
#pragma once

#include <vector>

#include "contact_table.h"
#include "particles.h"
#include "periodic.h"

namespace dem {

// The new slot order: order[k] is the slot that moves to slot k. Ties (a
// cell's particles) keep id order, so the order depends on positions and
// ids only.
template <int Dim>
std::vector<Slot> spatial_order(const Particles<Dim>& particles, const Periodic<Dim>& periodic, double range);

// Moves every particle to its new slot and renames the slots in the contact
// table's keys (rows keep their history and orientation).
template <int Dim>
void reorder_particles(Particles<Dim>& particles, ContactTable<Dim>& contacts, const std::vector<Slot>& order);

}  // namespace dem
