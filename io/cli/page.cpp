// `clumpkit page DIR [DIR ...] [--out DIR]`: a static page to browse output folders offline.
#include "io/pipeline/page.h"
#include "io/cli/common.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_page(CLI::App& app) {
  struct Opts {
    std::vector<std::string> dirs;
    std::string out;
    std::size_t max_spheres = PageOptions{}.max_spheres;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "page",
      "A static HTML page to browse an output folder offline (file://, no server, no network): "
      "a library or shape set (a 3-D view of each particle's mesh, translucent, with its clump "
      "inside and the spheres reaching outside it in red; descriptors and fidelity in a table "
      "that sorts by a click on a column and filters; the renders as thumbnails), a specimen "
      "(its spheres, instanced, coloured by body, size, kind, zone or porosity band, cut at a "
      "height; the "
      "report; the slices), an element test or CPT (the curves as plots that read out a point; "
      "several test folders of one kind side by side with --out), a crushing run (the results "
      "table, each particle's force against travel and its cells before and after, the Weibull "
      "and size plots). Writes "
      "DIR/index.html and DIR/page/ (three.js of Debian's libjs-three with its licence, the "
      "data as scripts). A folder without manifest.json, a damaged file or a mix of folders is "
      "refused and nothing is written.");
  c->add_option("DIR", o->dirs, "Output folder(s) of clumpkit")->required();
  c->add_option("--out", o->out, "Where the page goes (required for several folders)");
  c->add_option("--max-spheres", o->max_spheres,
                "A specimen's spheres drawn at most (every k-th beyond, the full count stated)")
      ->check(CLI::PositiveNumber);
  c->add_flag("--json", o->json, "Print the page's path, kind and item count as JSON");
  c->callback([o] {
    PageOptions p;
    for (const std::string& d : o->dirs) p.dirs.emplace_back(d);
    p.out = o->out;
    p.max_spheres = o->max_spheres;
    const PageResult r = write_page(p);
    if (o->json) {
      std::cout << nlohmann::json{{"index", r.index.string()}, {"kind", r.kind}, {"items", r.items}}
                       .dump(2)
                << "\n";
      return;
    }
    std::printf("page: %s (%s, %zu %s)\n", r.index.string().c_str(), r.kind.c_str(), r.items,
                r.kind == "library"    ? "particles"
                : r.kind == "specimen" ? "spheres"
                : r.kind == "crush"    ? "particles"
                                       : "curve rows");
  });
}

}  // namespace clumpkit::cli
