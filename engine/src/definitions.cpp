#include "dem/definitions.h"

namespace dem {

WorldDef default_world_def() {
  WorldDef def;
  def.materials.push_back(MaterialDef{"default", 1000.0, 0.5, 0.0});
  def.contact_models.push_back(ContactModelDef{});
  return def;
}

}  // namespace dem
