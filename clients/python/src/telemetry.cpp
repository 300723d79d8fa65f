// Telemetry for Python: dem::client::TelemetrySubscription's callbacks run
// on the subscription's own thread and only put samples in a queue (no
// Python, no GIL there); Python takes them out with get() - waiting with the
// GIL released - or drain(). Iteration and callbacks on a Python thread are
// built on these in dem/telemetry.py.
#include "dem/client/telemetry.h"

#include <pybind11/stl.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <variant>

#include "bindings.h"
#include "client_handle.h"

namespace dem::python {

namespace py = pybind11;

namespace {

using Sample = std::variant<protocol::PlateForces, protocol::ContactStats, protocol::Status, protocol::RegionTelemetry>;

// The samples a subscription delivered and Python has not taken yet. When
// Python falls `capacity` samples behind, the oldest go (counted), so a
// subscriber nobody reads cannot grow without bound.
class SampleQueue {
 public:
  explicit SampleQueue(std::size_t capacity) : capacity_(capacity) {}

  void push(Sample sample) {
    {
      std::lock_guard lock(mutex_);
      if (samples_.size() >= capacity_) {
        samples_.pop_front();
        ++dropped_;
      }
      samples_.push_back(std::move(sample));
    }
    arrived_.notify_all();
  }

  std::optional<Sample> pop(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    if (!arrived_.wait_for(lock, timeout, [&] { return !samples_.empty() || closed_; })) return std::nullopt;
    if (samples_.empty()) return std::nullopt;
    Sample sample = std::move(samples_.front());
    samples_.pop_front();
    return sample;
  }

  std::deque<Sample> take_all() {
    std::lock_guard lock(mutex_);
    return std::exchange(samples_, {});
  }

  void close() {
    {
      std::lock_guard lock(mutex_);
      closed_ = true;
    }
    arrived_.notify_all();
  }

  std::uint64_t dropped() const {
    std::lock_guard lock(mutex_);
    return dropped_;
  }

 private:
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable arrived_;
  std::deque<Sample> samples_;
  std::uint64_t dropped_ = 0;
  bool closed_ = false;
};

py::object to_python(Sample sample) {
  return std::visit([](auto&& value) { return py::cast(std::move(value)); }, std::move(sample));
}

class Telemetry {
 public:
  Telemetry(const ClientHandle& handle, bool plate_forces, bool contact_stats, bool status, std::size_t capacity,
            bool region_measures)
      : client_(handle.client), queue_(std::make_shared<SampleQueue>(capacity)) {
    if (!client_) throw std::runtime_error("this client is closed");
    client::TelemetryCallbacks callbacks;
    const auto enqueue = [queue = queue_](const auto& sample) { queue->push(sample); };
    if (plate_forces) callbacks.plate_forces = enqueue;
    if (contact_stats) callbacks.contact_stats = enqueue;
    if (status) callbacks.status = enqueue;
    if (region_measures) callbacks.region_measures = enqueue;
    subscription_ = std::make_unique<client::TelemetrySubscription>(*client_, std::move(callbacks));
  }

  // The next sample, or None after `timeout` seconds without one (or once closed).
  py::object get(double timeout) {
    std::optional<Sample> sample;
    {
      py::gil_scoped_release release;
      sample = queue_->pop(std::chrono::milliseconds(static_cast<std::int64_t>(std::max(0.0, timeout) * 1000.0)));
    }
    return sample ? to_python(std::move(*sample)) : py::none();
  }

  py::list drain() {
    py::list samples;
    for (Sample& sample : queue_->take_all()) samples.append(to_python(std::move(sample)));
    return samples;
  }

  std::uint32_t matched_publishers() const { return subscription_ ? subscription_->matched_publishers() : 0; }
  std::uint64_t dropped() const { return queue_->dropped(); }
  bool closed() const { return !subscription_; }

  void close() {
    queue_->close();
    std::unique_ptr<client::TelemetrySubscription> subscription = std::move(subscription_);
    std::shared_ptr<client::Client> client = std::move(client_);
    py::gil_scoped_release release;  // joining the subscription's thread
    subscription.reset();
    client.reset();
  }

 private:
  std::shared_ptr<client::Client> client_;  // its participant must outlive the subscription
  std::shared_ptr<SampleQueue> queue_;
  std::unique_ptr<client::TelemetrySubscription> subscription_;
};

}  // namespace

void bind_telemetry(py::module_& m) {
  py::class_<Telemetry>(m, "Telemetry", "A server's telemetry, queued for Python (dem::client::TelemetrySubscription)")
      .def(py::init<const ClientHandle&, bool, bool, bool, std::size_t, bool>(), py::arg("client"),
           py::arg("plate_forces"), py::arg("contact_stats"), py::arg("status"), py::arg("capacity"),
           py::arg("region_measures") = false)
      .def("get", &Telemetry::get, py::arg("timeout"),
           "The next sample (PlateForces, ContactStats, Status or RegionTelemetry), or None after timeout seconds")
      .def("drain", &Telemetry::drain, "Every sample queued now, oldest first")
      .def_property_readonly("matched_publishers", &Telemetry::matched_publishers)
      .def_property_readonly("dropped", &Telemetry::dropped, "samples dropped because Python fell behind")
      .def_property_readonly("closed", &Telemetry::closed)
      .def("close", &Telemetry::close);
}

}  // namespace dem::python
