"""A server's telemetry in Python: plate forces (dem.PlateForces), contact
statistics (dem.ContactStats) and, if asked, status (dem.Status) and the
measures of the case's regions (dem.RegionTelemetry), in the order they
arrived. The C++ subscription queues them on a thread of its own; the
server never waits for this reader.

    with press.subscribe() as telemetry:
        press.start_cycle(5000)
        for sample in telemetry.samples(timeout=2.0):      # until 2 s of silence
            if isinstance(sample, dem.PlateForces):
                print(sample.cycle, sample.wall("top").normal_stress)

or with a callback, called on a thread of the subscription's own:

    telemetry = press.subscribe(callback=lambda sample: print(sample))
"""

import threading
import time

from . import _client


class Subscription:
    """Telemetry of one server (made by Client.subscribe)."""

    def __init__(self, native, callback=None):
        self._native = native
        self._thread = None
        if callback is not None:
            self._thread = threading.Thread(target=self._dispatch, args=(callback,),
                                            name="dem-telemetry", daemon=True)
            self._thread.start()

    def get(self, timeout=None):
        """The next sample, or None after ``timeout`` s without one (None:
        wait until one comes or the subscription closes)."""
        if timeout is not None:
            return self._native.get(timeout)
        while not self._native.closed:
            sample = self._native.get(0.2)
            if sample is not None:
                return sample
        return None

    def drain(self):
        """Every sample that has arrived and not been taken, oldest first."""
        return self._native.drain()

    def samples(self, timeout):
        """Yields samples until none has come for ``timeout`` s."""
        while True:
            sample = self._native.get(timeout)
            if sample is None:
                return
            yield sample

    def __iter__(self):
        """Every sample until the subscription is closed."""
        while True:
            sample = self.get()
            if sample is None:
                return
            yield sample

    def wait_for_publisher(self, timeout=10.0):
        """Waits until the server's telemetry writers are matched (discovery),
        so no sample published from now on is missed; False on timeout."""
        deadline = time.monotonic() + timeout
        while self._native.matched_publishers == 0:
            if time.monotonic() >= deadline:
                return False
            time.sleep(0.01)
        return True

    @property
    def dropped(self):
        """Samples dropped because this reader fell ``capacity`` behind."""
        return self._native.dropped

    @property
    def closed(self):
        return self._native.closed

    def close(self):
        """Stops the subscription (and its callback thread)."""
        if not self._native.closed:
            self._native.close()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _dispatch(self, callback):
        while not self._native.closed:
            sample = self._native.get(0.2)
            if sample is not None:
                callback(sample)


PlateForces = _client.PlateForces
ContactStats = _client.ContactStats
Status = _client.Status
RegionTelemetry = _client.RegionTelemetry
RegionMeasures = _client.RegionMeasures
