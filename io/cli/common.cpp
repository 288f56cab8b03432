#include "io/cli/common.h"

#include "geom/errors.h"
#include "io/pipeline/page.h"

#include <algorithm>

#include <tbb/global_control.h>

#include <time.h>
#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace clumpkit::cli {

namespace {
double now() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}
std::unique_ptr<tbb::global_control> g_threads;

std::atomic<bool> g_stop_requested{false};
std::atomic<long> g_first_signal_second{0};

// Lock-free atomics and clock_gettime are async-signal-safe.
extern "C" void on_stop_signal(int signal) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  if (!g_stop_requested.exchange(true)) {
    g_first_signal_second = now.tv_sec;
  } else if (now.tv_sec > g_first_signal_second + 1) {
    // Asked again, seconds later: end at once. (Not at the second signal itself: `timeout` and
    // some launchers send it to the process and to its group, i.e. twice.)
    std::signal(signal, SIG_DFL);
    std::raise(signal);
  }
}
}  // namespace

void set_threads(int threads) {
  g_threads = limit_threads(threads);
}

void add_recipe_job_options(CLI::App* command, RecipeJobOptions& options,
                            const std::string& recipe_help, JobKind kind,
                            const std::string& json_help) {
  command->add_option("--recipe", options.recipe, recipe_help)->required();
  command
      ->add_option("--out", options.out,
                   "Output directory (written as DIR.partial and renamed at the end; an earlier "
                   "clumpkit output there is replaced)")
      ->required();
  command->add_flag("--page", options.page,
                    "Also write DIR/index.html, a page to browse the results offline (clumpkit "
                    "page DIR)");
  add_job_options(command, options.job, kind, json_help);
}

void finish_page(const RecipeJobOptions& options) {
  if (!options.page) return;
  PageOptions p;
  p.dirs = {options.out};
  const PageResult r = write_page(p);
  if (!options.job.json) std::printf("page: %s\n", r.index.string().c_str());
}

void add_job_options(CLI::App* command, JobOptions& options, JobKind kind,
                     const std::string& json_help) {
  command->add_option("--threads", options.threads, "Worker threads (0 = all cores)")
      ->capture_default_str();
  if (kind == JobKind::staged) {
    command
        ->add_option("--checkpoint-seconds", options.checkpoint_seconds,
                     "Wall-clock seconds between checkpoints in DIR.partial (0: only on Ctrl-C)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    command->add_flag("--resume", options.resume,
                      "Continue the checkpoint kept in DIR.partial by a killed or interrupted run "
                      "(same bytes as an uninterrupted run)");
  }
  command->add_flag("--quiet", options.quiet, "No progress bar");
  command->add_flag("--json", options.json, json_help);
}

ProgressBar::ProgressBar(std::string label, bool quiet)
    : label_(std::move(label)), enabled_(!quiet && isatty(fileno(stderr))), start_(now()) {}

ProgressBar::~ProgressBar() {
  finish();
}

void ProgressBar::update(const Progress& progress) {
  if (!enabled_) return;
  const double fraction = std::clamp(progress.fraction, 0.0, 1.0);
  const int permille = static_cast<int>(1000 * fraction);
  if (permille == last_permille_) return;
  last_permille_ = permille;
  const double elapsed = now() - start_;
  const double eta = fraction > 0 ? elapsed * (1.0 / fraction - 1.0) : 0.0;
  const int width = 30, fill = permille * width / 1000;
  const std::string count =
      progress.total > 0 ? std::to_string(progress.done) + "/" + std::to_string(progress.total)
                         : std::to_string(permille / 10) + " %";
  std::fprintf(stderr, "\r%s [%.*s%*s] %s  %.0fs elapsed, %.0fs left ", label_.c_str(), fill,
               "##############################", width - fill, "", count.c_str(), elapsed, eta);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

Interrupter signal_interrupter(ProgressBar& bar, const std::string& command) {
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
  return [&bar, command](std::string_view stage, Progress progress) {
    // "library: library" says the stage twice: a stage named after its command is the command.
    bar.set_label(stage == command ? command : command + ": " + std::string(stage));
    bar.update(progress);
    return g_stop_requested.load();
  };
}

void add_weld_option(CLI::App* command, double& weld_tolerance) {
  command
      ->add_option("--weld-tolerance", weld_tolerance,
                   "Merge vertices closer than this fraction of the bounding-box diagonal (0: "
                   "equal positions only, the seam copies of OBJ and PLY exporters; STL at least "
                   "1e-9)")
      ->capture_default_str();
}

CLI::Option* add_length_unit_option(CLI::App* command, std::string& symbol,
                                    const std::string& help) {
  if (symbol.empty()) symbol = "L";
  return command->add_option("--length-unit", symbol, help);
}

void add_repair_options(CLI::App* command, RepairOptions& options, std::string& wrap) {
  command
      ->add_option("--min-component", options.min_component,
                   "Remove components with fewer triangles than this fraction of the largest "
                   "one's (fins, loose triangles, debris); 0 keeps all")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  wrap = to_string(options.wrap);
  command
      ->add_option("--wrap", wrap,
                   "When to replace the closed surface by its alpha wrap (CGAL 3D Alpha "
                   "Wrapping: watertight, manifold, free of crossings by construction): "
                   "fallback (only when faces still cross after the local mend and the union), "
                   "always, never (crossings left are refused)")
      ->capture_default_str()
      ->check(CLI::IsMember({"fallback", "always", "never"}));
  command
      ->add_option("--wrap-alpha", options.wrap_alpha,
                   "The wrap's alpha as a fraction of the bounding-box diagonal: cavities and "
                   "gaps narrower than about this are bridged")
      ->capture_default_str()
      ->check(CLI::Range(1e-6, 1.0));
  command
      ->add_option("--wrap-offset", options.wrap_offset,
                   "How far outside the surface the wrap lies, as a fraction of the bounding-box "
                   "diagonal (adds about offset x area to the volume)")
      ->capture_default_str()
      ->check(CLI::Range(1e-7, 1.0));
}

RepairOptions repair_options_from(RepairOptions options, const std::string& wrap) {
  options.wrap = wrap_mode_from_string(wrap, "--wrap");
  return options;
}

void note(const std::string& message) {
  std::fprintf(stderr, "clumpkit: note: %s\n", message.c_str());
}

void add_max_memory_option(CLI::App* command, double& gib, const std::string& refused) {
  command->add_option("--max-memory", gib,
                      "Refuse " + refused + " (default: half of this machine's memory)");
}

double max_memory_bytes(double gib) {
  if (!(gib >= 0) || !std::isfinite(gib))
    throw InvalidInput("--max-memory must be a positive number of GiB, got " + std::to_string(gib));
  if (gib > 0) return gib * 1073741824.0;
  return 0.5 * double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
}

void warn_redone(const std::string& out, const std::vector<std::string>& redone) {
  for (const std::string& f : redone)
    warning(out + ".partial/" + f + " was damaged (checksum): particle redone");
}

void warning(const std::string& message) {
  std::fprintf(stderr, "clumpkit: warning: %s\n", message.c_str());
}

}  // namespace clumpkit::cli
