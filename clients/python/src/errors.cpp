// The C++ client's exceptions become the Python exceptions of dem.errors
// (defined in Python so they carry attributes and docstrings): one place,
// as rclpy turns rcl's return codes into exceptions.
#include "dem/client/errors.h"

#include <pybind11/pybind11.h>

#include "bindings.h"
#include "dem/dds/error.h"

namespace dem::python {

namespace py = pybind11;

namespace {

void raise(const char* name, const py::tuple& arguments) {
  try {
    const py::object type = py::module_::import("dem.errors").attr(name);
    const py::object error = type(*arguments);
    PyErr_SetObject(type.ptr(), error.ptr());
  } catch (py::error_already_set& failure) {
    // dem.errors could not be imported: that error is the one to see.
    failure.restore();
  }
}

}  // namespace

void bind_errors(py::module_&) {
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const client::ServerError& error) {
      const protocol::Reply& reply = error.reply();
      const auto kind = protocol::command_kind(reply.kind);
      raise("ServerError", py::make_tuple(std::string(protocol::to_string(reply.status)), reply.message,
                                          kind ? std::string(protocol::to_string(*kind)) : "unknown", py::cast(reply)));
    } catch (const client::InterfaceMismatch& error) {
      raise("InterfaceMismatch", py::make_tuple(error.what()));
    } catch (const client::NoSuchServer& error) {
      raise("NoSuchServer", py::make_tuple(error.what()));
    } catch (const client::LocalFileError& error) {
      PyErr_SetString(PyExc_OSError, error.what());
    } catch (const client::ReplyTimeout& error) {
      raise("ReplyTimeout", py::make_tuple(error.what()));
    } catch (const dds::DdsError& error) {
      raise("DdsError", py::make_tuple(error.what()));
    }
  });
}

}  // namespace dem::python
