// Shared pieces of the clumpkit subcommands: registration, threads, progress bar, interruption.
#pragma once

#include "dem/run/stage_store.h"
#include "geom/mesh/repair.h"
#include "geom/progress.h"
#include "io/pipeline/threads.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace clumpkit::cli {

/// Each subcommand file registers itself on the root app.
void register_shape(CLI::App& app);
void register_shapes(CLI::App& app);
void register_describe(CLI::App& app);
void register_refine(CLI::App& app);
void register_fill(CLI::App& app);
void register_library(CLI::App& app);
void register_volume(CLI::App& app);
void register_specimen(CLI::App& app);
void register_export(CLI::App& app);
void register_import(CLI::App& app);
void register_test(CLI::App& app);
void register_compare_curves(CLI::App& app);
void register_cells(CLI::App& app);
void register_crush(CLI::App& app);
void register_specimen_scale(CLI::App& app);
void register_page(CLI::App& app);

void register_repair(CLI::App& app);

/// The --weld-tolerance option of the commands that read a mesh (MeshReadOptions).
void add_weld_option(CLI::App* command, double& weld_tolerance);

/// The --length-unit option of the geometry commands (docs/units.md), read into `symbol`
/// (default "L", the input's own unit); length_unit (io/base/units.h) checks it. `help` replaces
/// the text that speaks of a mesh. Returns the option (its count() says whether it was given).
CLI::Option* add_length_unit_option(CLI::App* command, std::string& symbol,
                                    const std::string& help =
                                        "The input mesh's length unit, e.g. mm: only labels the "
                                        "output (default L, the mesh's unit)");

/// The options of the repair chain (geom/mesh/repair.h), for `repair` and `fill --repair`:
/// --min-component, --wrap, --wrap-alpha, --wrap-offset. `wrap` receives the text of --wrap;
/// repair_options_from turns it into the mode after parsing.
void add_repair_options(CLI::App* command, RepairOptions& options, std::string& wrap);
/// `options` with the mode of `wrap` ("fallback", "always" or "never").
RepairOptions repair_options_from(RepairOptions options, const std::string& wrap);

/// The options every job command shares, declared by one call (add_job_options).
struct JobOptions {
  int threads = kAllCores;  ///< --threads (io/pipeline/threads.h)
  bool quiet = false;       ///< --quiet: no progress bar
  bool json = false;        ///< --json: one JSON object on stdout
  bool resume = false;      ///< --resume (staged jobs)
  /// --checkpoint-seconds (staged jobs): wall-clock seconds between checkpoints.
  double checkpoint_seconds = dem::StageControl{}.checkpoint_every_seconds;
};

/// A parallel job takes --threads, --quiet and --json; a staged one (checkpoints in DIR.partial)
/// also --checkpoint-seconds and --resume.
enum class JobKind { parallel, staged };

/// Adds the job options of `kind` to `command`, bound to `options`; `json_help` says what --json
/// prints.
void add_job_options(CLI::App* command, JobOptions& options, JobKind kind,
                     const std::string& json_help);

/// A job that runs a recipe into an output directory.
struct RecipeJobOptions {
  std::string recipe;  ///< --recipe
  std::string out;     ///< --out
  JobOptions job;
  bool page = false;  ///< --page: DIR/index.html when the job is done (clumpkit page)
};

/// Adds --recipe (`recipe_help` says which kind) and --out, both required, --page, then the job
/// options of `kind` (add_job_options).
void add_recipe_job_options(CLI::App* command, RecipeJobOptions& options,
                            const std::string& recipe_help, JobKind kind,
                            const std::string& json_help);

/// After a recipe job: its page in the output folder when --page was given (clumpkit page), its
/// path printed unless --json.
void finish_page(const RecipeJobOptions& options);

/// Limits the worker threads for the rest of the command (limit_threads's rule and check).
void set_threads(int threads);

/// Progress bar on stderr, drawn only when stderr is a terminal and not --quiet.
class ProgressBar {
 public:
  ProgressBar(std::string label, bool quiet);
  ~ProgressBar();
  /// The bar at `progress`: the job's own units ("12/40") where it counts them, else a
  /// percentage.
  void update(const Progress& progress);
  /// Changes the label (e.g. the current stage) from the next update on.
  void set_label(std::string label) {
    if (label == label_) return;
    label_ = std::move(label);
    last_permille_ = -1;
  }
  void finish();

 private:
  std::string label_;
  bool enabled_;
  double start_;
  int last_permille_ = -1;
  bool drawn_ = false;
};

/// The interrupter of a long command (geom/progress.h): shows the stage and fraction on `bar`
/// (label "COMMAND: stage", or "COMMAND" for the stage named after it) and asks the work to stop
/// once SIGINT or SIGTERM has arrived. The handlers are installed on the first call; a signal more
/// than a second after the first ends the process at once. main() maps the resulting Interrupted to
/// exit code 130.
Interrupter signal_interrupter(ProgressBar& bar, const std::string& command);

/// Writes one note line "clumpkit: note: ..." to stderr.
void note(const std::string& message);

/// The memory budget of --max-memory GIB in bytes: `gib` GiB when positive, otherwise half of
/// this machine's physical memory. Throws InvalidInput for a NaN or negative value.
double max_memory_bytes(double gib);

/// Adds --max-memory GIB to `command`, read into `gib` (0: the default): "Refuse `refused`
/// (default: half of this machine's memory)"; max_memory_bytes turns it into bytes.
void add_max_memory_option(CLI::App* command, double& gib, const std::string& refused);

/// Writes one warning line "clumpkit: warning: ..." to stderr (the command still succeeds).
void warning(const std::string& message);

/// One warning per damaged per-particle record of an earlier run in OUT.partial (`redone`,
/// paths inside it) that a resumed job redid.
void warn_redone(const std::string& out, const std::vector<std::string>& redone);

}  // namespace clumpkit::cli
