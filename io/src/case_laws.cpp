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

// The restitution law's e is ContactModelDef's own, read by its list (case_rules.h).
void set_law_parameters(const google::protobuf::Message& parameters, ContactModelDef& def) {
  if (dynamic_cast<const proto::LinearLaw*>(&parameters) != nullptr ||
      dynamic_cast<const proto::LinearRestitutionLaw*>(&parameters) != nullptr) {
    read_fields(parameters, def.linear);  // both linear laws' stiffnesses, by LinearLawDef's list
  } else if (dynamic_cast<const proto::HertzLaw*>(&parameters) != nullptr) {
    read_fields(parameters, def.hertz);
  }
}

}  // namespace dem::io
