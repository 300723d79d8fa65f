#include "case_laws.h"

#include "case_fields.h"
#include "dem/law_traits.h"

namespace dem::io {

CaseLaw case_law(const proto::ContactModel& model) {
  CaseLaw found;
  if (model.law_case() == proto::ContactModel::LAW_NOT_SET) return found;
  found.field = model.GetDescriptor()->FindFieldByNumber(model.law_case());
  found.parameters = &model.GetReflection()->GetMessage(model, found.field);
  found.law = contact_law_named(found.field->name());
  return found;
}

void set_law_parameters(const google::protobuf::Message& parameters, ContactModelDef& def) {
  const auto* restitution = dynamic_cast<const proto::LinearRestitutionLaw*>(&parameters);
  if (restitution != nullptr || dynamic_cast<const proto::LinearLaw*>(&parameters) != nullptr) {
    read_fields(parameters, def.linear);  // both linear laws' stiffnesses, by LinearLawDef's list
    if (restitution != nullptr) def.restitution = restitution->restitution();
  } else if (dynamic_cast<const proto::HertzLaw*>(&parameters) != nullptr) {
    read_fields(parameters, def.hertz);
  }
}

}  // namespace dem::io
