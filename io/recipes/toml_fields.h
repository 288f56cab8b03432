// Typed reads of TOML values with the one-line "FILE: FIELD: what, got VALUE" errors recipes use.
#pragma once

#include "geom/shapes/distribution.h"

#include <toml++/toml.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace clumpkit {

/// The value as a short text for messages ("nan", "[1, 2]", "{ a = 1 }").
std::string toml_show(const toml::node& n);

/// Readers bound to one file; every failure throws InvalidInput naming file, field and value.
struct TomlFields {
  std::string file;

  [[noreturn]] void fail(const std::string& field, const std::string& why) const;
  double number(const toml::node& n, const std::string& field) const;    ///< finite int or float
  double positive(const toml::node& n, const std::string& field) const;  ///< number > 0
  double non_negative(const toml::node& n, const std::string& field) const;  ///< number >= 0
  std::pair<double, double> pair(const toml::node& n, const std::string& field) const;
  /// A non-empty array of finite numbers (FIELD[i] named in errors).
  std::vector<double> numbers(const toml::node& n, const std::string& field) const;
  long long integer(const toml::node& n, const std::string& field) const;
  /// An integer in [lo, hi]: "must be in [lo, hi], got VALUE" otherwise.
  int integer_in(const toml::node& n, const std::string& field, long long lo, long long hi) const;
  std::string string(const toml::node& n, const std::string& field) const;
  const toml::table& table(const toml::node& n, const std::string& field) const;
  /// A number, or one of { uniform = [a, b] }, { integers = [a, b] }, { normal = { mu, sigma,
  /// min, max } }, { lognormal = { mu, sigma, min, max } } (geom/shapes/distribution.h).
  Distribution distribution(const toml::node& n, const std::string& field) const;
};

/// A recipe's top-level keys with their readers, in the order an unknown key's message lists
/// them.
using TopLevelReaders = std::vector<std::pair<std::string, std::function<void(const toml::node&)>>>;

/// Reads every key of `root` by its entry in `readers`; an unknown key is refused as
/// "FILE: KEY: unknown key (known: ...)".
void read_top_level(const TomlFields& f, const toml::table& root, const TopLevelReaders& readers);

/// Parses TOML text; a syntax error throws InvalidInput "FILE:LINE: TOML syntax error: ...".
toml::table parse_toml(const std::string& text, const std::string& path);

}  // namespace clumpkit
