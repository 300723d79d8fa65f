#include "case_laws.h"

#include "dem/law_traits.h"

namespace dem::io {

namespace {

HertzDampingDef to_hertz_damping(const proto::HertzLaw& law) {
  HertzDampingDef def;
  if (law.has_damping_ratio()) def.damping_ratio = law.damping_ratio();
  if (law.has_restitution()) def.restitution = law.restitution();
  def.tangential = law.tangential_damping();
  return def;
}

}  // namespace

CaseLaw case_law(const proto::ContactModel& model) {
  CaseLaw found;
  if (model.law_case() == proto::ContactModel::LAW_NOT_SET) return found;
  found.field = model.GetDescriptor()->FindFieldByNumber(model.law_case());
  found.parameters = &model.GetReflection()->GetMessage(model, found.field);
  found.law = contact_law_named(found.field->name());
  return found;
}

void set_law_parameters(const google::protobuf::Message& parameters, ContactModelDef& def) {
  if (const auto* linear = dynamic_cast<const proto::LinearLaw*>(&parameters)) {
    def.linear = {linear->normal_stiffness(), linear->shear_stiffness()};
  } else if (const auto* restitution = dynamic_cast<const proto::LinearRestitutionLaw*>(&parameters)) {
    def.linear = {restitution->normal_stiffness(), restitution->shear_stiffness()};
    def.restitution = restitution->restitution();
  } else if (const auto* hertz = dynamic_cast<const proto::HertzLaw*>(&parameters)) {
    def.hertz = to_hertz_damping(*hertz);
  }
}

}  // namespace dem::io
