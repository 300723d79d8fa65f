// dds::TypeSupport for the service's messages (see dem/dds/type_support.h):
// the bridge to the idlc-generated C types, which only type_support.cpp sees.
#pragma once

#include "dem/dds/type_support.h"
#include "dem/protocol/messages.h"

namespace dem::dds {

#define DEM_PROTOCOL_TYPE_SUPPORT(Type)                                  \
  template <>                                                            \
  struct TypeSupport<protocol::Type> {                                   \
    static const dds_topic_descriptor_t* descriptor();                   \
    static dds_return_t write(dds_entity_t writer, const protocol::Type& value); \
    static protocol::Type from_sample(const void* sample);               \
  };

DEM_PROTOCOL_TYPE_SUPPORT(Command)
DEM_PROTOCOL_TYPE_SUPPORT(Reply)
DEM_PROTOCOL_TYPE_SUPPORT(Status)
DEM_PROTOCOL_TYPE_SUPPORT(PlateForces)
DEM_PROTOCOL_TYPE_SUPPORT(ContactStats)
DEM_PROTOCOL_TYPE_SUPPORT(RegionTelemetry)

#undef DEM_PROTOCOL_TYPE_SUPPORT

}  // namespace dem::dds
