#include "io/cli/common.h"

#include <tbb/global_control.h>

#include <unistd.h>
#include <chrono>
#include <cstdio>
#include <memory>

namespace clumpkit::cli {

namespace {
double now() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}
std::unique_ptr<tbb::global_control> g_threads;
}  // namespace

void set_threads(int threads) {
  if (threads > 0)
    g_threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      static_cast<std::size_t>(threads));
}

ProgressBar::ProgressBar(std::string label, bool quiet)
    : label_(std::move(label)), enabled_(!quiet && isatty(fileno(stderr))), start_(now()) {}

ProgressBar::~ProgressBar() {
  finish();
}

void ProgressBar::update(std::size_t done, std::size_t total) {
  if (!enabled_ || total == 0) return;
  const int permille = static_cast<int>(1000 * done / total);
  if (permille == last_permille_) return;
  last_permille_ = permille;
  const double elapsed = now() - start_;
  const double eta = done > 0 ? elapsed * (double(total) / double(done) - 1.0) : 0.0;
  const int width = 30, fill = permille * width / 1000;
  std::fprintf(stderr, "\r%s [%.*s%*s] %zu/%zu  %.0fs elapsed, %.0fs left ", label_.c_str(), fill,
               "##############################", width - fill, "", done, total, elapsed, eta);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

void note(const std::string& message) {
  std::fprintf(stderr, "clumpkit: note: %s\n", message.c_str());
}

}  // namespace clumpkit::cli
