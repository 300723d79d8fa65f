// The contact law a case's contact model sets: the field of its `law` oneof,
// whose name is the engine's name of the law (dem/law_traits.h), and the
// message of that field, which carries the law's parameters. Laws that take
// the same parameters share a message (HertzLaw), so a new law of that kind
// is only its field in case.proto.
#pragma once

#include <google/protobuf/descriptor.h>

#include <optional>

#include "dem/case.pb.h"
#include "dem/definitions.h"

namespace dem::io {

struct CaseLaw {
  const google::protobuf::FieldDescriptor* field = nullptr;  // none: the model sets no law
  const google::protobuf::Message* parameters = nullptr;
  std::optional<ContactLaw> law;  // none: the field names no law of the engine's
};

CaseLaw case_law(const proto::ContactModel& model);

// The law's parameters from its message, by the message's type.
void set_law_parameters(const google::protobuf::Message& parameters, ContactModelDef& def);

}  // namespace dem::io
