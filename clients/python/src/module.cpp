// dem._client: the C++ client library (dem::client) exposed to Python. The
// friendly API is the pure-Python package around it (dem/client.py); this
// module keeps to the C++ library's own calls and types.
#include <pybind11/pybind11.h>

#include "bindings.h"

PYBIND11_MODULE(_client, module) {
  module.doc() = "The C++ client of dem_server (dem::client), wrapped by the dem package";
  dem::python::bind_messages(module);
  dem::python::bind_errors(module);
  dem::python::bind_client(module);
  dem::python::bind_telemetry(module);
  dem::python::bind_tap(module);
}
