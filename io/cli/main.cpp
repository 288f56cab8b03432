// clumpkit command line: parses arguments and maps errors to exit codes (2 bad input, 1 failure,
// 130 stopped on request).
#include "geom/errors.h"
#include "geom/version.h"
#include "io/cli/common.h"

#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) would otherwise kill us mid-write with no word; ignored, the
  // write fails with EFBIG and the atomic writer reports it and keeps the earlier file.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{
      "clumpkit " CLUMPKIT_VERSION
      " - irregular particles, sphere clumps and DEM specimens for geomaterials.\n"
      "Geometry commands keep the units of their input; recipes are in SI units (m, kg, s)."};
  // The version, the commit and the libraries compiled in: what a bug report needs.
  std::string version = clumpkit::version_text();
  version.pop_back();  // CLI11 ends the text with its own newline
  app.set_version_flag("--version", version);
  app.require_subcommand(1);
  clumpkit::cli::register_shape(app);
  clumpkit::cli::register_shapes(app);
  clumpkit::cli::register_describe(app);
  clumpkit::cli::register_refine(app);
  clumpkit::cli::register_repair(app);
  clumpkit::cli::register_fill(app);
  clumpkit::cli::register_library(app);
  clumpkit::cli::register_volume(app);
  clumpkit::cli::register_specimen(app);
  clumpkit::cli::register_export(app);
  clumpkit::cli::register_import(app);
  clumpkit::cli::register_specimen_scale(app);
  clumpkit::cli::register_test(app);
  clumpkit::cli::register_compare_curves(app);
  clumpkit::cli::register_cells(app);
  clumpkit::cli::register_crush(app);
  clumpkit::cli::register_page(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "clumpkit: error: %s (see --help)\n", e.what());
    return 2;
  } catch (const clumpkit::InvalidInput& e) {
    std::fprintf(stderr, "clumpkit: error: %s\n", e.what());
    return 2;
  } catch (const clumpkit::IoError& e) {
    std::fprintf(stderr, "clumpkit: error: %s\n", e.what());
    return 2;
  } catch (const clumpkit::Interrupted& e) {
    std::fprintf(stderr, "clumpkit: stopped: %s\n", e.what());
    return 130;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clumpkit: error: internal failure: %s\n", e.what());
    return 1;
  }
  return 0;
}
