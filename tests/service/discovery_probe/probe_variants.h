// The other descriptions of the server's type names (variant_*.idl),
// compiled by idlc; each variant's descriptors are renamed at build time
// (tests/service/CMakeLists.txt), as they share the server's type names.
#pragma once

#include <dds/dds.h>

#define DEM_PROBE_VARIANT(variant)                                            \
  extern "C" const dds_topic_descriptor_t probe_##variant##_Command_desc;     \
  extern "C" const dds_topic_descriptor_t probe_##variant##_Reply_desc;       \
  extern "C" const dds_topic_descriptor_t probe_##variant##_Status_desc;      \
  extern "C" const dds_topic_descriptor_t probe_##variant##_PlateForces_desc; \
  extern "C" const dds_topic_descriptor_t probe_##variant##_ContactStats_desc;

DEM_PROBE_VARIANT(final)
DEM_PROBE_VARIANT(appendable)
DEM_PROBE_VARIANT(mutable)

#undef DEM_PROBE_VARIANT
