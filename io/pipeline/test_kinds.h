// The registry of `clumpkit test` kinds: each kind's loading path, job, report fields and plots in
// one entry (io/pipeline/test_kind.h), from which the command's help, the job, the page and
// docs/lab-tests.md are made.
#pragma once

#include "io/pipeline/test_kind.h"

#include <string>
#include <vector>

namespace clumpkit {

/// Every kind, in the order the help lists them.
const std::vector<TestKind>& test_kinds();

/// The kind named `name`; throws InvalidInput naming the known kinds.
const TestKind& find_test_kind(const std::string& name);

/// The kinds' names as the help lists them: "isotropic, oedometer, …, triaxial-p or cpt".
std::string test_kind_names();

}  // namespace clumpkit
