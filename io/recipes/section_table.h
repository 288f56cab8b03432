// One table per recipe section: each key's unit, range, default and help beside the code that
// reads it into the spec, so that reading (unknown keys refused, naming the known ones) and the
// recipe reference (docs/recipes.md) come from the same place.
#pragma once

#include "geom/format.h"
#include "geom/range.h"
#include "io/recipes/toml_fields.h"

#include <toml++/toml.h>

#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace clumpkit {

/// One key of a section, reading into a spec of type Spec.
template <class Spec>
struct RecipeKey {
  std::string name;
  std::string unit;   ///< SI unit, or "" for a number without one
  std::string range;  ///< what values it takes, as the reference prints it
  std::string help;
  /// Reads the value at `field` ("section.key") into the spec; throws InvalidInput through `f`.
  std::function<void(const TomlFields& f, const toml::node& value, const std::string& field,
                     Spec& spec)>
      read;
  /// The default, as text, read off a default-constructed spec.
  std::function<std::string(const Spec& defaults)> shown;
};

/// A section: its name in the recipe, what it is, and its keys in the order the reference lists.
template <class Spec>
struct RecipeSection {
  std::string name;
  std::string help;
  std::vector<RecipeKey<Spec>> keys;
};

/// How a number key is read: TomlFields::number (finite), positive or non_negative.
using NumberRead = double (TomlFields::*)(const toml::node&, const std::string&) const;

/// A further check of a number read (throws through `f`, naming `field` and showing `value`).
using NumberCheck = std::function<void(const TomlFields& f, const std::string& field,
                                       const toml::node& value, double x)>;

/// A number key whose value lands in the double `at(spec)`, read by `get` and then `check`.
template <class Spec, class At>
RecipeKey<Spec> number_key(std::string name, std::string unit, std::string range, std::string help,
                           At at, NumberRead get = &TomlFields::number, NumberCheck check = {}) {
  RecipeKey<Spec> k{std::move(name), std::move(unit), std::move(range), std::move(help), {}, {}};
  k.read = [at, get, check](const TomlFields& f, const toml::node& v, const std::string& field,
                            Spec& s) {
    const double x = (f.*get)(v, field);
    if (check) check(f, field, v, x);
    at(s) = x;
  };
  k.shown = [at](const Spec& defaults) {
    Spec copy = defaults;
    return format_number(at(copy));
  };
  return k;
}

/// A number key whose allowed values are the engine's `range` (geom/range.h): read (an integer
/// when the range is of integers), refused outside it in the range's own words, "FIELD: must be
/// in [a, b], got VALUE", and quoted by the reference from the same object. `at(spec)` is the
/// double or integer the value lands in (an integer range's value exactly, a seed above 2^53
/// too); its default is shown as that number.
template <class Spec, class At>
RecipeKey<Spec> range_key(std::string name, std::string unit, const Range& range, std::string help,
                          At at) {
  RecipeKey<Spec> k{std::move(name), std::move(unit), range.text(), std::move(help), {}, {}};
  k.read = [at, range](const TomlFields& f, const toml::node& v, const std::string& field,
                       Spec& s) {
    using T = std::remove_reference_t<decltype(at(s))>;
    const long long n = range.integer ? f.integer(v, field) : 0;
    const double x = range.integer ? static_cast<double>(n) : f.number(v, field);
    const std::string why = outside(range, x);
    if (!why.empty()) f.fail(field, why + ", got " + toml_show(v));
    if constexpr (std::is_integral_v<T>) {
      if (x > static_cast<double>(std::numeric_limits<T>::max()) ||
          x < static_cast<double>(std::numeric_limits<T>::lowest()))
        f.fail(field, "is too large, got " + toml_show(v));
      at(s) = range.integer ? static_cast<T>(n) : static_cast<T>(x);
    } else {
      at(s) = static_cast<T>(x);
    }
  };
  k.shown = [at](const Spec& defaults) {
    Spec copy = defaults;
    if constexpr (std::is_integral_v<std::remove_reference_t<decltype(at(copy))>>)
      return std::to_string(at(copy));
    else
      return format_number(at(copy));
  };
  return k;
}

/// The key `k` with its default shown as `text` (a default that is a rule, not a number).
template <class Spec>
RecipeKey<Spec> shown_as(RecipeKey<Spec> k, std::string text) {
  k.shown = [text](const Spec&) { return text; };
  return k;
}

/// The key `k` of an inner spec, read into and shown from `at(spec)` (a PolyhedronParams&
/// within a set, say), so that one table of keys serves every section that holds the spec.
template <class Spec, class Inner, class At>
RecipeKey<Spec> nested_key(const RecipeKey<Inner>& k, At at) {
  RecipeKey<Spec> out{k.name, k.unit, k.range, k.help, {}, {}};
  out.read = [read = k.read, at](const TomlFields& f, const toml::node& v, const std::string& field,
                                 Spec& s) { read(f, v, field, at(s)); };
  out.shown = [shown = k.shown, at](const Spec& defaults) {
    Spec copy = defaults;
    return shown(at(copy));
  };
  return out;
}

/// A key read by its own code (`read`), its default shown as `shown`.
template <class Spec>
RecipeKey<Spec> custom_key(
    std::string name, std::string unit, std::string range, std::string help, std::string shown,
    std::function<void(const TomlFields&, const toml::node&, const std::string&, Spec&)> read) {
  RecipeKey<Spec> k{std::move(name), std::move(unit), std::move(range),
                    std::move(help), std::move(read), {}};
  return shown_as(std::move(k), std::move(shown));
}

/// Reads the table `value` of section `s` into `spec`: every key through its table entry, an
/// unknown one refused as "FILE: SECTION.KEY: unknown key (known: ...)". Returns the keys given.
template <class Spec>
std::vector<std::string> read_section(const TomlFields& f, const toml::node& value,
                                      const RecipeSection<Spec>& s, Spec& spec) {
  std::vector<std::string> given;
  for (const auto& [key, v] : f.table(value, s.name)) {
    const std::string k(key.str()), field = s.name + "." + k;
    const RecipeKey<Spec>* entry = nullptr;
    for (const auto& candidate : s.keys)
      if (candidate.name == k) entry = &candidate;
    if (!entry) {
      std::string known;
      for (const auto& candidate : s.keys) known += (known.empty() ? "" : ", ") + candidate.name;
      f.fail(field, "unknown key (known: " + known + ")");
    }
    entry->read(f, v, field, spec);
    given.push_back(k);
  }
  return given;
}

/// The section as Markdown: a heading ("### [NAME]", or `heading` when given), its help, and a
/// table of key, unit, range, default, help.
template <class Spec>
std::string section_reference(const RecipeSection<Spec>& s, const Spec& defaults,
                              const std::string& heading = "") {
  std::string md =
      (heading.empty() ? "### [" + s.name + "]" : "### " + heading) + "\n\n" + s.help + "\n\n";
  md += "| key | unit | values | default | what |\n|---|---|---|---|---|\n";
  for (const auto& k : s.keys)
    md += "| `" + k.name + "` | " + k.unit + " | " + k.range + " | " + k.shown(defaults) + " | " +
          k.help + " |\n";
  return md;
}

}  // namespace clumpkit
