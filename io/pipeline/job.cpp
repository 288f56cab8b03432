#include "io/pipeline/job.h"

#include "geom/errors.h"
#include "geom/hash.h"
#include "io/base/atomic_file.h"
#include "io/base/text.h"
#include "io/reports/report.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

namespace fs = std::filesystem;

namespace clumpkit {

void check_output_directory(const std::string& dir) {
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw InvalidInput(dir + ": --out exists and is not a directory");
  if (fs::exists(dir) && !fs::exists(fs::path(dir) / "manifest.json") && !fs::is_empty(dir))
    throw InvalidInput(dir +
                       ": output directory exists and is not a clumpkit output; "
                       "remove it or choose another --out");
}

bool lies_within(const std::string& path, const std::string& dir) {
  std::error_code ec;
  const fs::path d = fs::weakly_canonical(dir, ec), p = fs::weakly_canonical(path, ec);
  return !d.empty() && std::mismatch(d.begin(), d.end(), p.begin(), p.end()).first == d.end();
}

void check_output_spares(const std::string& dir, const std::string& input,
                         const std::string& what) {
  if (lies_within(input, dir))
    throw InvalidInput("--out " + dir + " would replace " + what + " " + input +
                       ": choose another --out");
}

void check_not_input(const std::string& out, const std::string& option, const std::string& in) {
  std::error_code ec;  // hard links are the same file too
  if (fs::equivalent(out, in, ec) || lies_within(out, in))
    throw InvalidInput(option + " " + out + " is the input " + in +
                       ", which would be overwritten: choose another output");
}

void publish_directory(const std::string& staging, const std::string& dir) {
  std::error_code ec;
  if (fs::exists(dir)) {
    check_output_directory(dir);
    fs::remove_all(dir, ec);
    if (ec) throw IoError(dir + ": cannot replace output directory: " + ec.message());
  }
  fs::rename(staging, dir, ec);
  if (ec) throw IoError(dir + ": cannot move finished output into place: " + ec.message());
}

std::vector<int> particle_fractions(const ShapeRecipe& recipe) {
  std::vector<int> f;
  for (std::size_t k = 0; k < recipe.fractions.size(); ++k)
    f.insert(f.end(), static_cast<std::size_t>(recipe.fractions[k].count), static_cast<int>(k));
  return f;
}

nlohmann::ordered_json manifest_head(const std::string& command, const std::string& recipe_path,
                                     const std::string& recipe_text, std::uint64_t seed) {
  nlohmann::ordered_json m;
  m["tool"] = "clumpkit";
  m["format_version"] = kManifestFormat;
  m["version"] = CLUMPKIT_VERSION;
  m["command"] = command;
  m["recipe_path"] = recipe_path;
  m["recipe"] = recipe_text;
  m["seed"] = seed;
  return m;
}

nlohmann::ordered_json manifest_head(const std::string& command, const ShapeRecipe& recipe) {
  nlohmann::ordered_json m = manifest_head(command, recipe.path, recipe.text, recipe.seed);
  m["particles"] = particle_fractions(recipe).size();
  return m;
}

void for_each_particle(const ShapeRecipe& recipe, const std::vector<int>& fraction_of,
                       const std::vector<char>& todo, std::size_t already,
                       const std::function<void(std::size_t)>& work, std::string_view stage,
                       const Interrupter& interrupter) {
  const std::size_t total = fraction_of.size();
  std::atomic<std::size_t> done{already};
  std::exception_ptr error;
  std::atomic<bool> failed{false}, stop{false};
  std::mutex report_mutex;
  const auto fraction = [total](std::size_t n) {
    return total ? static_cast<double>(n) / static_cast<double>(total) : 1.0;
  };
  if (already > 0 && interrupted(interrupter, stage, fraction(already))) stop = true;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, total, 1),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) {
                        if ((!todo.empty() && !todo[i]) || failed || stop) continue;
                        try {
                          work(i);
                        } catch (const std::exception& e) {
                          if (!failed.exchange(true)) {
                            try {
                              throw InvalidInput(recipe.path + ": fraction '" +
                                                 recipe.fractions[fraction_of[i]].name +
                                                 "' particle " + id_name(i) + ": " + e.what());
                            } catch (...) {
                              error = std::current_exception();
                            }
                          }
                          return;
                        }
                        const std::size_t n = ++done;
                        // Not concurrently: a thread that finds the interrupter busy goes on.
                        if (interrupter && report_mutex.try_lock()) {
                          if (interrupter(stage, fraction(n))) stop = true;
                          report_mutex.unlock();
                        }
                      }
                    });
  if (error) std::rethrow_exception(error);
  if (stop)
    throw Interrupted(recipe.path + ": " + std::string(stage) + " stopped on request after " +
                      std::to_string(done.load()) + " of " + std::to_string(total) + " particles");
}

std::string record_checksum(const nlohmann::ordered_json& record) {
  Fnv1a h;
  h.add(std::string_view(record.dump()));
  return h.hex();
}

void write_sealed_record(const std::string& path, const nlohmann::ordered_json& record) {
  nlohmann::ordered_json sealed = record;
  sealed["checksum"] = record_checksum(record);
  write_file_atomically(path, [&](std::ostream& o) { o << sealed.dump(1) << "\n"; });
}

bool read_sealed_record(const std::string& path, nlohmann::ordered_json& record) {
  try {
    nlohmann::ordered_json r = nlohmann::ordered_json::parse(read_file(path));
    const std::string stored = r.value("checksum", std::string());
    r.erase("checksum");
    if (stored != record_checksum(r)) return false;
    record = std::move(r);
    return true;
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

nlohmann::json read_json_file(const std::string& path) {
  const std::string text = read_file(path, "JSON file");
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInput(path + ": not valid JSON (" + e.what() + ")");
  }
}

std::string begin_staging(const std::string& dir) {
  check_output_directory(dir);
  const std::filesystem::path staging = dir + ".partial";
  std::error_code ec;
  std::filesystem::remove_all(staging, ec);
  std::filesystem::create_directories(staging, ec);
  if (ec) throw IoError(staging.string() + ": cannot create directory: " + ec.message());
  return staging.string();
}

}  // namespace clumpkit
