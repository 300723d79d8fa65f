// Contacts as a numpy structured array: one row per contact, a column per
// member of protocol::ContactEntry (its Fields, generated from the IDL),
// laid out as a C struct of those members would be; vectors as (3,)
// sub-arrays, z = 0 in 2D.
#pragma once

#include <pybind11/numpy.h>

#include <vector>

#include "dem/protocol/messages.h"

namespace dem::python {

pybind11::dtype contact_dtype();
pybind11::array contact_array(const std::vector<protocol::ContactEntry>& contacts);

}  // namespace dem::python
