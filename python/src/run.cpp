#include "python/src/run.h"

#include "geom/errors.h"

#include <atomic>
#include <chrono>
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

// What the worker's interrupter leaves for the main thread, and the main thread's answer.
// What the worker reported since the main thread last looked: the latest fraction of each stage
// entered meanwhile, in order, so a stage shorter than the polling interval is still reported.
struct Mailbox {
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::vector<std::pair<std::string, double>> pending;
};

}  // namespace

void run_interruptible(const std::function<void(const Interrupter&)>& work,
                       const py::object& progress) {
  auto box = std::make_shared<Mailbox>();
  const Interrupter interrupter = [box](std::string_view stage, double fraction) {
    {
      const std::lock_guard<std::mutex> lock(box->mutex);
      if (!box->pending.empty() && box->pending.back().first == stage)
        box->pending.back().second = fraction;
      else
        box->pending.emplace_back(std::string(stage), fraction);
    }
    return box->stop.load();
  };
  std::promise<void> done;
  std::future<void> finished = done.get_future();
  std::thread worker;
  {
    py::gil_scoped_release release;
    worker = std::thread([&work, &interrupter, &done] {
      try {
        work(interrupter);
        done.set_value();
      } catch (...) {
        done.set_exception(std::current_exception());
      }
    });
  }
  std::optional<py::error_already_set> raised;  // Ctrl-C, or an error of the progress callable
  bool over = false;
  while (!over) {
    {
      py::gil_scoped_release release;
      over = finished.wait_for(std::chrono::milliseconds(50)) == std::future_status::ready;
    }
    if (raised) continue;  // stopping: wait for the worker only
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress.is_none()) {
        std::vector<std::pair<std::string, double>> updates;
        {
          const std::lock_guard<std::mutex> lock(box->mutex);
          std::swap(updates, box->pending);
        }
        for (const auto& [stage, fraction] : updates) progress(stage, fraction);
      }
    } catch (py::error_already_set& e) {
      raised.emplace(std::move(e));
      box->stop = true;
    }
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
