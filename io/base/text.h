// The text plumbing of every reader: the one whole-file reader, comma-separated cells, and
// locale-independent numbers that must fill their whole token.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace clumpkit {

/// The bytes of the file at `path`. Throws IoError "PATH: file not found", "PATH: is a
/// directory, not a WHAT", "PATH: cannot open WHAT: <reason>" or "PATH: read failed".
std::string read_file(const std::string& path, const std::string& what = "file");

/// The cells of one CSV line between commas, as written by clumpkit (no quoting); a trailing
/// comma adds no empty cell.
std::vector<std::string> split_csv(const std::string& line);

/// The number that is all of `token` (a leading '+' allowed; "inf" and "nan" are numbers, the
/// caller checks finiteness), or nothing. std::from_chars: the same in every locale, unlike
/// strtod, which would read "1,5" as 1.5 under a German locale.
std::optional<double> to_number(std::string_view token);

/// The integer that is all of `token` (a leading '+' allowed), or nothing.
std::optional<long long> to_integer(std::string_view token);

/// Where a line-by-line reader is: its file and line number, for errors that name both, and
/// the finite number of one field ("PATH:LINE: field F: not a finite number: 'CELL'").
struct LineReader {
  std::string path;
  long line = 0;
  /// Throws InvalidInput "PATH:LINE: why".
  [[noreturn]] void fail(const std::string& why) const;
  double number(const std::string& cell, const char* field) const;
};

/// CSV cell: quoted (with doubled quotes) when it holds a comma, quote or newline.
std::string csv_escape(const std::string& s);

/// Five-digit zero-padded particle id ("00042"), the file stem of per-particle outputs.
std::string id_name(std::size_t i);

}  // namespace clumpkit
