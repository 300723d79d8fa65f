#include "contact_array.h"

namespace dem::python {

namespace py = pybind11;

void register_contact_dtype() {
  PYBIND11_NUMPY_DTYPE(ContactRow, first, second_particle, second_wall, point, normal, overlap, normal_force,
                       shear_force, normal_damping, shear_damping, sliding);
}

py::dtype contact_dtype() { return py::dtype::of<ContactRow>(); }

py::array contact_array(const std::vector<protocol::ContactEntry>& contacts) {
  py::array_t<ContactRow> array(static_cast<py::ssize_t>(contacts.size()));
  ContactRow* rows = array.mutable_data();
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const protocol::ContactEntry& c = contacts[i];
    rows[i] = ContactRow{c.first,
                         c.second_particle,
                         c.second_wall,
                         {c.point.x, c.point.y, c.point.z},
                         {c.normal.x, c.normal.y, c.normal.z},
                         c.overlap,
                         c.normal_force,
                         c.shear_force,
                         c.normal_damping,
                         c.shear_damping,
                         c.sliding};
  }
  return array;
}

}  // namespace dem::python
