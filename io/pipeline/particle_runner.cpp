#include "io/pipeline/particle_runner.h"

#include "geom/errors.h"
#include "io/base/text.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <exception>
#include <mutex>
#include <string>

namespace clumpkit {

void for_each_particle(const ShapeRecipe& recipe, const std::vector<int>& fraction_of,
                       const std::vector<char>& todo, std::size_t already,
                       const std::function<void(std::size_t)>& work, std::string_view stage,
                       const Interrupter& interrupter) {
  const std::size_t total = fraction_of.size();
  std::atomic<std::size_t> done{already};
  std::exception_ptr error;
  std::atomic<bool> failed{false}, stop{false};
  std::mutex report_mutex;
  if (already > 0 && interrupted(interrupter, stage, Progress(already, total))) stop = true;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, total, 1),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) {
                        if ((!todo.empty() && !todo[i]) || failed || stop) continue;
                        try {
                          work(i);
                        } catch (const std::exception& e) {
                          if (!failed.exchange(true)) {
                            try {
                              throw InvalidInput(recipe.path + ": fraction '" +
                                                 recipe.fractions[fraction_of[i]].name +
                                                 "' particle " + id_name(i) + ": " + e.what());
                            } catch (...) {
                              error = std::current_exception();
                            }
                          }
                          return;
                        }
                        const std::size_t n = ++done;
                        // Not concurrently: a thread that finds the interrupter busy goes on.
                        if (interrupter && report_mutex.try_lock()) {
                          if (interrupter(stage, Progress(n, total))) stop = true;
                          report_mutex.unlock();
                        }
                      }
                    });
  if (error) std::rethrow_exception(error);
  if (stop)
    throw Interrupted(recipe.path + ": " + std::string(stage) + " stopped on request after " +
                      std::to_string(done.load()) + " of " + std::to_string(total) + " particles");
}

}  // namespace clumpkit
