// The one number formatter: doubles as text for files (exact round trip) and for messages.
#pragma once

#include <string>

namespace clumpkit {

/// Shortest of the 15-, 16- and 17-significant-digit "%g" texts that reads back to the same
/// double, so CSV, JSON, OBJ and stage records are exact and byte-identical across runs.
std::string format_number(double v);

/// `v` with `digits` significant digits ("%.*g"), for messages and labels.
std::string format_number(double v, int digits);

/// `v` rounded to `digits` significant digits, as a double: views and page data need no more
/// than six, and their files shrink threefold. Non-finite values and zero pass unchanged.
double round_significant(double v, int digits);

/// `v` with `decimals` digits after the point ("%.*f"), for plot labels and file names.
std::string format_fixed(double v, int decimals);

}  // namespace clumpkit
