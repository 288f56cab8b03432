#include "io/recipes/toml_fields.h"

#include "geom/errors.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace clumpkit {

std::string toml_show(const toml::node& n) {
  std::ostringstream s;
  if (auto v = n.as_floating_point()) {
    s.precision(10);
    s << v->get();
    return s.str();
  }
  if (n.is_table()) {
    s << *n.as_table();
    return s.str();
  }
  if (n.is_array()) {
    s << *n.as_array();
    return s.str();
  }
  n.visit([&](const auto& v) { s << v; });
  return s.str();
}

void read_top_level(const TomlFields& f, const toml::table& root, const TopLevelReaders& readers) {
  for (const auto& [key, val] : root) {
    const std::string k(key.str());
    const auto it =
        std::find_if(readers.begin(), readers.end(), [&](const auto& e) { return e.first == k; });
    if (it == readers.end()) {
      std::string known;
      for (const auto& e : readers) known += (known.empty() ? "" : ", ") + e.first;
      f.fail(k, "unknown key (known: " + known + ")");
    }
    it->second(val);
  }
}

void TomlFields::fail(const std::string& field, const std::string& why) const {
  throw InvalidInput(file + ": " + field + ": " + why);
}

double TomlFields::number(const toml::node& n, const std::string& field) const {
  if (!n.is_integer() && !n.is_floating_point())
    fail(field, "expected a number, got " + toml_show(n));
  const double x =
      n.is_integer() ? static_cast<double>(n.as_integer()->get()) : n.as_floating_point()->get();
  if (!std::isfinite(x)) fail(field, "must be finite, got " + toml_show(n));
  return x;
}

std::pair<double, double> TomlFields::pair(const toml::node& n, const std::string& field) const {
  const auto* a = n.as_array();
  if (!a || a->size() != 2) fail(field, "expected [low, high], got " + toml_show(n));
  return {number(*a->get(0), field), number(*a->get(1), field)};
}

std::vector<double> TomlFields::numbers(const toml::node& n, const std::string& field) const {
  const auto* a = n.as_array();
  if (!a || a->empty()) fail(field, "expected a non-empty array of numbers, got " + toml_show(n));
  std::vector<double> v;
  for (std::size_t i = 0; i < a->size(); ++i)
    v.push_back(number(*a->get(i), field + "[" + std::to_string(i) + "]"));
  return v;
}

long long TomlFields::integer(const toml::node& n, const std::string& field) const {
  const auto* i = n.as_integer();
  if (!i) fail(field, "expected an integer, got " + toml_show(n));
  return i->get();
}

int TomlFields::integer_in(const toml::node& n, const std::string& field, long long lo,
                           long long hi) const {
  const long long v = integer(n, field);
  if (v < lo || v > hi)
    fail(field, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                    toml_show(n));
  return static_cast<int>(v);
}

std::string TomlFields::string(const toml::node& n, const std::string& field) const {
  const auto* s = n.as_string();
  if (!s) fail(field, "expected a string, got " + toml_show(n));
  return s->get();
}

const toml::table& TomlFields::table(const toml::node& n, const std::string& field) const {
  const auto* t = n.as_table();
  if (!t) fail(field, "expected a table, got " + toml_show(n));
  return *t;
}

toml::table parse_toml(const std::string& text, const std::string& path) {
  try {
    return toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw InvalidInput(path + ":" + std::to_string(e.source().begin.line) +
                       ": TOML syntax error: " + std::string(e.description()));
  }
}

double TomlFields::positive(const toml::node& n, const std::string& field) const {
  const double v = number(n, field);
  if (!(v > 0.0)) fail(field, "must be positive, got " + toml_show(n));
  return v;
}

double TomlFields::non_negative(const toml::node& n, const std::string& field) const {
  const double v = number(n, field);
  if (!(v >= 0.0)) fail(field, "must be >= 0, got " + toml_show(n));
  return v;
}

Distribution TomlFields::distribution(const toml::node& n, const std::string& field) const {
  if (n.is_number()) return constant(number(n, field));
  const auto* t = n.as_table();
  if (!t || t->size() != 1)
    fail(field, "expected a number or one of {uniform|integers|normal|lognormal = ...}, got " +
                    toml_show(n));
  const auto first = t->begin();
  const std::string k(first->first.str());
  const toml::node& val = first->second;
  Distribution d;
  if (k == "uniform" || k == "integers") {
    d.kind = k == "uniform" ? Distribution::Kind::Uniform : Distribution::Kind::Integers;
    std::tie(d.a, d.b) = pair(val, field + "." + k);
    return d;
  }
  if (k == "normal" || k == "lognormal") {
    d.kind = k == "normal" ? Distribution::Kind::Normal : Distribution::Kind::Lognormal;
    const auto* p = val.as_table();
    if (!p)
      fail(field + "." + k,
           "expected { mu = .., sigma = .., min = .., max = .. }, got " + toml_show(val));
    // The parameters: mu and sigma (required) into a and b, the truncation into min and max.
    struct Parameter {
      const char* name;
      double Distribution::*at;
      bool given;
    };
    Parameter known[] = {{"mu", &Distribution::a, false},
                         {"sigma", &Distribution::b, false},
                         {"min", &Distribution::min, false},
                         {"max", &Distribution::max, false}};
    for (const auto& [pk, pv] : *p) {
      const std::string name(pk.str());
      const std::string f = field + "." + k + "." + name;
      Parameter* hit = nullptr;
      for (Parameter& q : known)
        if (name == q.name) hit = &q;
      if (!hit) fail(f, "unknown key (known: mu, sigma, min, max)");
      d.*(hit->at) = number(pv, f);
      hit->given = true;
    }
    if (!known[0].given || !known[1].given) fail(field + "." + k, "needs both mu and sigma");
    return d;
  }
  fail(field + "." + k, "unknown distribution (known: uniform, integers, normal, lognormal)");
  return d;
}

}  // namespace clumpkit
