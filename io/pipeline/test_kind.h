// One kind of `clumpkit test`: its loading path, job, report fields and plots (the registry of
// kinds is io/pipeline/test_kinds.h).
#pragma once

#include "dem/lab/element_loading.h"
#include "geom/progress.h"
#include "io/pipeline/lab_setup.h"
#include "io/recipes/lab_recipe.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace clumpkit {

/// What a kind's report reads: the curve of the test and what it was run with.
struct TestReportInput {
  const std::vector<dem::CurveRow>& curve;
  const dem::ElementTestSettings& settings;
  const TestRecipe& recipe;
  const std::vector<double>& work;  ///< input work (J/m³) per row of a crushable test, else empty
  bool crushable = false;
};

/// curve.png of an element test: the row's values on each axis and their labels.
struct CurvePicture {
  const char* x_label;
  const char* y_label;
  double (*x)(const dem::CurveRow&);
  double (*y)(const dem::CurveRow&);
};

/// A plot of the page: curve.csv's columns x and y (bare names, "axial_stress": matched through
/// column_name) times fx and fy (x as log10 when log_x).
struct PagePlot {
  std::string title, x_label, y_label, x, y;
  double fx = 1, fy = 1;
  bool log_x = false;
};

struct TestKind;

/// A test job (element test or CPT) of `kind`.
using TestJob = LabJobResult (*)(const TestKind& kind, const std::string& specimen_dir,
                                 const TestRecipe& recipe, const std::string& out_dir,
                                 const LabJobOptions& options, const Interrupter& interrupter);

/// One kind of `clumpkit test`. Adding a kind: its loading path (dem/lab/element_loading.h,
/// loading_paths.cpp), its report function and its entry in test_kinds()
/// (io/pipeline/test_kinds.cpp); docs/layout.md shows the constant-p′ triaxial's three files as the
/// worked example.
struct TestKind {
  const char* name;
  /// One sentence for `clumpkit test --help` and docs/lab-tests.md: what the loading does and
  /// what report.json gets.
  const char* summary;
  /// How the cell is driven while loading; null for the CPT (a probe, its own job).
  const dem::LoadingPath* path;
  TestJob job;
  /// report.json's fields of the kind (element tests; null for the CPT, whose job writes them).
  void (*report)(const TestReportInput& in, nlohmann::ordered_json& rep);
  CurvePicture picture;  ///< element tests' curve.png (unused for the CPT)
  /// The page's plots of the kind (a crushable test adds the breakage plots).
  std::vector<PagePlot> page_plots;
};

}  // namespace clumpkit
