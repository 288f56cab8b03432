#include "io/recipes/lab_recipe.h"

#include "geom/errors.h"
#include "io/base/text.h"
#include "io/recipes/toml_fields.h"

#include <fstream>
#include <sstream>

namespace clumpkit {

namespace {

// [probe]: the cone and its push, checked by dem::validate_probe.
dem::ProbeSettings read_probe(const TomlFields& f, const toml::node& val) {
  const std::string k = "probe";
  dem::ProbeSettings p;
  bool have_depth = false;
  for (const auto& [pk, pv] : f.table(val, k)) {
    const std::string q(pk.str()), field = "probe." + q;
    if (q == "diameter") {
      p.diameter = f.number(pv, field);
    } else if (q == "apex_deg") {
      p.apex_deg = f.number(pv, field);
    } else if (q == "velocity") {
      p.velocity = f.number(pv, field);
    } else if (q == "depth") {
      p.depth = f.number(pv, field);
      have_depth = true;
    } else if (q == "friction") {
      p.friction = f.non_negative(pv, field);
    } else {
      f.fail(field, "unknown key (known: diameter, apex_deg, velocity, depth, friction)");
    }
  }
  if (!have_depth) f.fail("probe.depth", "is required (the push below the specimen's top, m)");
  try {
    dem::validate_probe(p);
  } catch (const InvalidInput& e) {
    throw InvalidInput(f.file + ": " + e.what());
  }
  return p;
}

}  // namespace

TestRecipe parse_test_recipe(const std::string& text, const std::string& path) {
  const TomlFields f{path};
  const toml::table root = parse_toml(text, path);
  TestRecipe r;
  r.path = path;
  r.text = text;
  dem::ElementTestSettings& s = r.settings;
  bool have_final = false;
  for (const auto& [key, val] : root) {
    const std::string k(key.str());
    if (k == "name" || k == "description") {
      f.string(val, k);
    } else if (k == "test") {
      for (const auto& [tk, tv] : f.table(val, k)) {
        const std::string t(tk.str()), field = "test." + t;
        if (t == "confining") {
          s.confining = f.positive(tv, field);
        } else if (t == "final_stress") {
          s.final_stress = f.positive(tv, field);
          have_final = true;
        } else if (t == "strain_rate") {
          s.strain_rate = f.positive(tv, field);
        } else if (t == "stress_rate") {
          s.stress_rate = f.positive(tv, field);
        } else if (t == "max_axial_strain") {
          s.max_axial_strain = f.positive(tv, field);
          if (s.max_axial_strain >= 0.9) f.fail(field, "must be below 0.9, got " + toml_show(tv));
        } else if (t == "critical_fraction") {
          r.critical_fraction = f.positive(tv, field);
          if (r.critical_fraction > 1) f.fail(field, "must be in (0, 1], got " + toml_show(tv));
        } else if (t == "friction") {
          s.friction = f.non_negative(tv, field);
        } else if (t == "servo_strain_rate") {
          s.servo_strain_rate = f.positive(tv, field);
        } else if (t == "consolidation_friction") {
          s.consolidation_friction = f.non_negative(tv, field);
        } else if (t == "record_every") {
          const long long n = f.integer(tv, field);
          if (n < 1 || n > 1000000) f.fail(field, "must be in [1, 1e6], got " + toml_show(tv));
          s.record_every = static_cast<int>(n);
        } else if (t == "timestep_safety") {
          r.timestep_safety = f.positive(tv, field);
          if (r.timestep_safety > 0.5) f.fail(field, "must be at most 0.5, got " + toml_show(tv));
        } else if (t == "modulus_range") {
          const auto range = f.pair(tv, field);
          if (!(range.first >= 0 && range.second > range.first))
            f.fail(field, "must be [lo, hi] with 0 <= lo < hi, got " + toml_show(tv));
          r.modulus_range = range;
        } else if (t == "consolidation_tolerance") {
          s.consolidation_tolerance = f.positive(tv, field);
        } else if (t == "density_scaling") {
          r.density_scaling = f.number(tv, field);
          if (!(r.density_scaling >= 1 && r.density_scaling <= 1e6))
            f.fail(field, "must be in [1, 1e6], got " + toml_show(tv));
        } else {
          f.fail(field,
                 "unknown key (known: confining, final_stress, strain_rate, stress_rate, "
                 "density_scaling, "
                 "max_axial_strain, critical_fraction, friction, consolidation_friction, "
                 "servo_strain_rate, record_every, timestep_safety, modulus_range, "
                 "consolidation_tolerance)");
        }
      }
    } else if (k == "contact") {
      for (const auto& [ck, cv] : f.table(val, k)) {
        const std::string c(ck.str()), field = "contact." + c;
        if (c == "stiffness_scaling") {
          const std::string v = f.string(cv, field);
          if (v == "none")
            r.scaling = dem::StiffnessScaling::none;
          else if (v == "linear")
            r.scaling = dem::StiffnessScaling::linear;
          else
            f.fail(field, "expected \"none\" or \"linear\", got " + toml_show(cv));
        } else if (c == "kn_ref") {
          r.kn_ref = f.positive(cv, field);
        } else if (c == "d_ref") {
          r.d_ref = f.positive(cv, field);
        } else if (c == "ks_over_kn") {
          r.ks_over_kn = f.non_negative(cv, field);
        } else if (c == "damping_ratio") {
          r.damping_ratio = f.non_negative(cv, field);
          if (*r.damping_ratio >= 1) f.fail(field, "must be below 1, got " + toml_show(cv));
        } else if (c == "local_damping") {
          r.local_damping = f.non_negative(cv, field);
          if (*r.local_damping >= 1) f.fail(field, "must be below 1, got " + toml_show(cv));
        } else {
          f.fail(field,
                 "unknown key (known: stiffness_scaling, kn_ref, d_ref, ks_over_kn, "
                 "damping_ratio, local_damping)");
        }
      }
    } else if (k == "probe") {
      r.probe = read_probe(f, val);
    } else {
      f.fail(k, "unknown key (known: name, description, test, contact, probe)");
    }
  }
  if (r.scaling == dem::StiffnessScaling::linear && !r.d_ref)
    f.fail("contact.d_ref", "is required with stiffness_scaling = \"linear\"");
  if (have_final && !(s.final_stress > s.confining))
    f.fail("test.final_stress", "must exceed test.confining");
  if (!have_final) s.final_stress = 4.0 * s.confining;
  return r;
}

TestRecipe read_test_recipe(const std::string& path) {
  return parse_test_recipe(read_file(path, "recipe file"), path);
}

}  // namespace clumpkit
