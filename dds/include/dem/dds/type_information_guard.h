// The type information of this program's own topic types, kept so that a
// peer's announcement cannot rewrite it (dds/src/cyclone_guards.cpp).
#pragma once

#include <dds/dds.h>

namespace dem::dds {

// Registers a descriptor's type information as this program's own: an
// announcement naming the same type identifiers with other dependencies is
// then refused as invalid, instead of poisoning the type in Cyclone's type
// library. Topic<T> calls it for every topic it creates; idempotent.
void protect_type_information(const dds_topic_descriptor_t& descriptor);

}  // namespace dem::dds
