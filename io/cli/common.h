// Shared pieces of the clumpkit subcommands: registration, error exit codes, progress bar.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>

namespace clumpkit::cli {

/// Each subcommand file registers itself on the root app.
void register_shape(CLI::App& app);
void register_shapes(CLI::App& app);
void register_describe(CLI::App& app);
void register_fill(CLI::App& app);
void register_library(CLI::App& app);
void register_volume(CLI::App& app);
void register_specimen(CLI::App& app);

/// Thread-count control shared by parallel subcommands: 0 = all cores.
void set_threads(int threads);

/// Progress bar on stderr, drawn only when stderr is a terminal and not --quiet.
class ProgressBar {
 public:
  ProgressBar(std::string label, bool quiet);
  ~ProgressBar();
  void update(std::size_t done, std::size_t total);
  /// Changes the label (e.g. the current stage) from the next update on.
  void set_label(std::string label) {
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

/// Writes one note line "clumpkit: note: ..." to stderr.
void note(const std::string& message);

}  // namespace clumpkit::cli
