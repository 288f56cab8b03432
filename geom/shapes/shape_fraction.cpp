#include "geom/shapes/shape_fraction.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/limits.h"
#include "geom/shapes/block.h"
#include "geom/shapes/hull.h"
#include "geom/shapes/polyhedron.h"
#include "geom/shapes/primitives.h"

#include <cmath>

namespace clumpkit {

namespace {
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

const std::map<std::string, std::vector<ParameterInfo>>& tables() {
  static const std::map<std::string, std::vector<ParameterInfo>> t = {
      {"block",
       {{"W", true, kNone, "width, the sieve size (Jin et al. 2017 §1.1) [m]"},
        {"L", false, kNone, "length [m]; give L and H, or L_over_H and W_split"},
        {"H", false, kNone, "height [m]"},
        {"L_over_H", false, kNone, "L/H ratio (Jin et al. 2017 Fig. 2: lognormal)"},
        {"W_split", false, 0.5, "W/H = (L/H)^W_split, in [0, 1]"},
        {"nd", false, 2, "segments per cuboid edge, Nd"},
        {"sl", false, 0.8, "lower radial scale factor, Sl"},
        {"su", false, 1.2, "upper radial scale factor, Su"}}},
      {"hull",
       {{"diameter", true, kNone, "diameter d of the sphere the points lie on [m]"},
        {"points", false, 20, "number of random points N"},
        {"roundness_min", false, 1.0, "lower bound of the weighted roundness band"},
        {"roundness_max", false, 10.0, "upper bound of the weighted roundness band"},
        {"aspect_min", false, 0.3, "smallest flattening factor drawn per attempt"},
        {"max_attempts", false, 2000, "attempts before giving up"}}},
      {"polyhedron",
       {{"diameter", true, kNone, "volume-equivalent diameter D [m]"},
        {"planes", false, 30, "number of random cutting planes"},
        {"E", false, 1.0, "elongation I/L"},
        {"F", false, 1.0, "flatness S/I"},
        {"offset_min", false, 0.6, "smallest plane distance / sphere radius"},
        {"offset_max", false, 0.95, "largest plane distance / sphere radius"}}},
      {"ellipsoid",
       {{"a", true, kNone, "semi-axis along x [m]"},
        {"b", true, kNone, "semi-axis along y [m]"},
        {"c", true, kNone, "semi-axis along z [m]"},
        {"level", false, 3, "icosphere subdivision level"}}},
  };
  return t;
}

std::string join(const std::vector<ParameterInfo>& t) {
  std::string s;
  for (const auto& p : t) s += (s.empty() ? "" : ", ") + p.name;
  return s;
}
}  // namespace

const std::vector<std::string>& shape_methods() {
  static const std::vector<std::string> m = {"block", "hull", "polyhedron", "ellipsoid"};
  return m;
}

const std::vector<ParameterInfo>& method_parameters(const std::string& method) {
  const auto it = tables().find(method);
  if (it == tables().end())
    throw InvalidInput("unknown method '" + method +
                       "' (known: block, hull, polyhedron, ellipsoid)");
  return it->second;
}

void validate(const FractionSpec& spec, const std::string& prefix) {
  if (spec.method == kMeshMethod) {  // files, a scale, and nothing to draw
    if (!spec.params.empty())
      throw InvalidInput(prefix + "." + spec.params.begin()->first +
                         ": unknown parameter for method mesh (known: folder, scale)");
    require(kMeshScale, spec.scale, prefix + ".scale");
    if (spec.count != static_cast<int>(spec.files.size()))
      throw InvalidInput(prefix + ".count: " + std::to_string(spec.count) + " particles but " +
                         std::to_string(spec.files.size()) + " mesh files");
    return;
  }
  const std::vector<ParameterInfo>* table = nullptr;
  try {
    table = &method_parameters(spec.method);
  } catch (const InvalidInput& e) {
    throw InvalidInput(prefix + ".method: " + e.what());
  }
  require(kFractionCount, spec.count, prefix + ".count");
  for (const auto& [name, d] : spec.params) {
    bool known = false;
    for (const auto& p : *table) known |= p.name == name;
    if (!known)
      throw InvalidInput(prefix + "." + name + ": unknown parameter for method " + spec.method +
                         " (known: " + join(*table) + ")");
    validate(d, prefix + "." + name);
  }
  for (const auto& p : *table)
    if (p.required && !spec.params.count(p.name))
      throw InvalidInput(prefix + "." + p.name + ": required by method " + spec.method);

  // Range checks on the bounds of every distribution, so that a bad recipe fails before any
  // particle is made.
  auto bounds = [&](const std::string& n, double lo, double hi, const char* rule) {
    const auto it = spec.params.find(n);
    if (it == spec.params.end()) return;
    const double a = lower_bound(it->second), b = upper_bound(it->second);
    if (!(a >= lo && b <= hi))
      throw InvalidInput(prefix + "." + n + ": " + rule + ", got " + describe(it->second));
  };
  const double inf = std::numeric_limits<double>::infinity();
  if (spec.method == "block") {
    for (const char* n : {"L", "W", "H", "L_over_H"})
      bounds(n, kMinLength, kMaxLength, "must be a size between 1e-30 and 1e30");
    bounds("W_split", 0.0, 1.0, "must be in [0, 1]");
    bounds("nd", 1, 64, "must be in [1, 64]");
    bounds("sl", 1e-300, inf, "must be positive");
    bounds("su", 1e-300, inf, "must be positive");
    const bool lh = spec.params.count("L") && spec.params.count("H");
    const bool ratio = spec.params.count("L_over_H");
    if (lh == ratio)
      throw InvalidInput(prefix + ": block needs either L and H, or L_over_H (not both)");
    const double sl = spec.params.count("sl") ? upper_bound(spec.params.at("sl")) : 0.8;
    const double su = spec.params.count("su") ? lower_bound(spec.params.at("su")) : 1.2;
    if (sl > su)
      throw InvalidInput(
          prefix + ".sl: must not exceed su, got sl=" +
          (spec.params.count("sl") ? describe(spec.params.at("sl")) : "0.8") +
          " su=" + (spec.params.count("su") ? describe(spec.params.at("su")) : "1.2"));
  } else if (spec.method == "hull") {
    bounds("diameter", kMinLength, kMaxLength, "must be a size between 1e-30 and 1e30");
    bounds("points", 4, 100000, "must be in [4, 100000]");
    bounds("roundness_min", 1.0, inf, "must be at least 1");
    bounds("roundness_max", 1.0, inf, "must be at least 1");
    bounds("aspect_min", 1e-300, 1.0, "must be in (0, 1]");
    bounds("max_attempts", 1, 1e9, "must be at least 1");
  } else if (spec.method == "polyhedron") {
    bounds("diameter", kMinLength, kMaxLength, "must be a size between 1e-30 and 1e30");
    bounds("planes", 0, 10000, "must be in [0, 10000]");
    bounds("E", 1e-300, 1.0, "must be in (0, 1]");
    bounds("F", 1e-300, 1.0, "must be in (0, 1]");
    bounds("offset_min", 1e-300, 1.0, "must be in (0, 1]");
    bounds("offset_max", 1e-300, 1.0, "must be in (0, 1]");
  } else if (spec.method == "ellipsoid") {
    for (const char* n : {"a", "b", "c"})
      bounds(n, kMinLength, kMaxLength, "must be a size between 1e-30 and 1e30");
    bounds("level", 0, 6, "must be in [0, 6]");
  }
}

GeneratedShape generate_shape(const FractionSpec& spec, Rng& rng) {
  if (spec.method == kMeshMethod)
    throw InvalidInput("fraction " + spec.name +
                       ": the particles of a mesh fraction are read "
                       "from their files, not generated");
  GeneratedShape g;
  // Draw every parameter in table order (fixed order => reproducible streams).
  std::map<std::string, double> v;
  for (const auto& p : method_parameters(spec.method)) {
    const auto it = spec.params.find(p.name);
    if (it != spec.params.end()) {
      v[p.name] = sample(it->second, rng);
      g.sampled.emplace_back(p.name, v[p.name]);
    } else if (!std::isnan(p.default_value)) {
      v[p.name] = p.default_value;
    }
  }
  auto as_int = [](double x) { return static_cast<int>(std::lround(x)); };
  if (spec.method == "block") {
    BlockParams b;
    b.W = v.at("W");
    if (v.count("L_over_H")) {
      const double r = v.at("L_over_H");
      b.H = b.W / std::pow(r, v.at("W_split"));
      b.L = b.H * r;
      g.sampled.emplace_back("L", b.L);
      g.sampled.emplace_back("H", b.H);
    } else {
      b.L = v.at("L");
      b.H = v.at("H");
    }
    b.nd = as_int(v.at("nd"));
    b.sl = v.at("sl");
    b.su = v.at("su");
    g.mesh = make_block(b, rng);
  } else if (spec.method == "hull") {
    HullParams h;
    h.diameter = v.at("diameter");
    h.points = as_int(v.at("points"));
    h.roundness_min = v.at("roundness_min");
    h.roundness_max = v.at("roundness_max");
    h.aspect_min = v.at("aspect_min");
    h.max_attempts = as_int(v.at("max_attempts"));
    HullResult r = make_hull(h, rng);
    g.mesh = std::move(r.mesh);
    g.attempts = r.attempts;
  } else if (spec.method == "polyhedron") {
    PolyhedronParams p;
    p.diameter = v.at("diameter");
    p.planes = as_int(v.at("planes"));
    p.E = v.at("E");
    p.F = v.at("F");
    p.offset_min = v.at("offset_min");
    p.offset_max = v.at("offset_max");
    g.mesh = make_polyhedron(p, rng);
  } else if (spec.method == "ellipsoid") {
    g.mesh = make_ellipsoid(Vec3(v.at("a"), v.at("b"), v.at("c")), as_int(v.at("level")));
  } else {
    method_parameters(spec.method);  // throws for an unknown method
  }
  return g;
}

}  // namespace clumpkit
