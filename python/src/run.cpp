#include "python/src/run.h"

#include "geom/errors.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace clumpkit::python {

namespace {

// What the worker's interrupter leaves for the main thread, and the main thread's answer: the
// latest fraction of each stage entered since the main thread last looked, in order (a stage
// shorter than the polling interval is still reported). With a progress callable, a report that
// starts a stage, advances it by 1 % or ends it is a milestone: the worker waits until the main
// thread has handed it to Python and checked for Ctrl-C, so a stop asked for there is seen
// before the work goes past it (at most about 100 waits a stage).
struct Mailbox {
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::pair<std::string, double>> pending;
  bool milestones = false;    // a progress callable is given
  std::uint64_t posted = 0;   // milestones posted by the worker
  std::uint64_t handled = 0;  // milestones the main thread has handed over
  bool finished = false;      // the worker is done
  std::string last_stage;     // of the last milestone
  double last_fraction = -1.0;
};

}  // namespace

void run_interruptible(const std::function<void(const Interrupter&)>& work,
                       const py::object& progress) {
  auto box = std::make_shared<Mailbox>();
  box->milestones = !progress.is_none();
  const Interrupter interrupter = [box](std::string_view stage, double fraction) {
    std::unique_lock<std::mutex> lock(box->mutex);
    if (!box->pending.empty() && box->pending.back().first == stage)
      box->pending.back().second = fraction;
    else
      box->pending.emplace_back(std::string(stage), fraction);
    const bool milestone = stage != box->last_stage || fraction >= box->last_fraction + 0.01 ||
                           (fraction >= 1.0 && box->last_fraction < 1.0);
    if (box->milestones && milestone && !box->stop.load()) {
      box->last_stage = std::string(stage);
      box->last_fraction = fraction;
      const std::uint64_t ticket = ++box->posted;
      box->changed.notify_all();
      box->changed.wait(lock, [&] { return box->handled >= ticket || box->stop.load(); });
    }
    return box->stop.load();
  };
  std::promise<void> done;
  std::future<void> finished = done.get_future();
  std::thread worker;
  {
    py::gil_scoped_release release;
    worker = std::thread([&work, &interrupter, &done, box] {
      try {
        work(interrupter);
        done.set_value();
      } catch (...) {
        done.set_exception(std::current_exception());
      }
      const std::lock_guard<std::mutex> lock(box->mutex);
      box->finished = true;
      box->changed.notify_all();
    });
  }
  std::optional<py::error_already_set> raised;  // Ctrl-C, or an error of the progress callable
  bool over = false;
  while (!over) {
    std::vector<std::pair<std::string, double>> updates;
    std::uint64_t ticket = 0;
    {
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock(box->mutex);
      // Woken by a milestone or the end at once; otherwise every 50 ms to check for Ctrl-C.
      box->changed.wait_for(lock, std::chrono::milliseconds(50),
                            [&] { return box->finished || box->posted > box->handled; });
      over = box->finished;
      ticket = box->posted;
      std::swap(updates, box->pending);
    }
    if (!raised) {
      try {
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (!progress.is_none())
          for (const auto& [stage, fraction] : updates) progress(stage, fraction);
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // asked for by progress
      } catch (py::error_already_set& e) {
        raised.emplace(std::move(e));
        box->stop = true;
      }
    }
    const std::lock_guard<std::mutex> lock(box->mutex);
    box->handled = ticket;
    box->changed.notify_all();
  }
  {
    py::gil_scoped_release release;
    worker.join();
  }
  if (raised) throw std::move(*raised);
  finished.get();
}

void register_exceptions() {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInput& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const IoError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const Interrupted& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    } catch (const NumericError& e) {
      PyErr_SetString(PyExc_ArithmeticError, e.what());
    }
  });
}

}  // namespace clumpkit::python
