#include "io/export/formats.h"

#include "io/export/lammps_molecules.h"
#include "io/export/liggghts.h"
#include "io/export/pfc.h"
#include "io/export/vtk.h"
#include "io/export/yade.h"

namespace clumpkit {

const std::vector<ExportFormat>& export_formats() {
  static const std::vector<ExportFormat> formats = {
      {"lammps",
       "data.specimen, bodies.infile (fix rigid/small infile), bodies_map.csv and in.clumpkit "
       "(gravity settle in the container; runs unchanged with mpirun -np N)",
       [](const ExportSource& src, const std::vector<SpecimenBody>& bodies, const std::string& dir,
          const LammpsDeck& deck) {
         std::vector<std::string> written = write_lammps_export(bodies, src.settings, dir, deck);
         if (src.templates) {  // templates also become molecules for fix deposit
           const std::vector<std::string> mol = write_lammps_molecules(bodies, src.settings, dir);
           written.insert(written.end(), mol.begin(), mol.end());
         }
         return written;
       },
       [] { return lammps_run_command(1); }},
      {"liggghts",
       "templates.liggghts (use_density: exact mass and inertia), one insertion per body, "
       "soil.liggghts, bodies_map.csv and in.clumpkit",
       [](const ExportSource& src, const std::vector<SpecimenBody>& bodies, const std::string& dir,
          const LammpsDeck&) { return write_liggghts_export(bodies, src.settings, dir); },
       liggghts_run_command},
      {"yade", "sphere files, specimen_bodies.txt, bodies_map.csv and run_clumpkit.py (yade -n -x)",
       [](const ExportSource& src, const std::vector<SpecimenBody>& bodies, const std::string& dir,
          const LammpsDeck&) { return write_yade_export(bodies, src.settings, dir); },
       yade_run_command},
      {"pfc", "clumpkit.p3dat (PFC 7 syntax, templates of unit density) and bodies_map.csv",
       [](const ExportSource& src, const std::vector<SpecimenBody>& bodies, const std::string& dir,
          const LammpsDeck&) { return write_pfc_export(bodies, src.settings, dir); },
       pfc_run_command},
      {"vtk", "specimen.vtp and glyph_clumpkit.py",
       [](const ExportSource&, const std::vector<SpecimenBody>& bodies, const std::string& dir,
          const LammpsDeck&) { return write_vtk_export(bodies, dir); },
       vtk_run_command},
  };
  return formats;
}

const ExportFormat* find_export_format(const std::string& name) {
  for (const ExportFormat& f : export_formats())
    if (name == f.name) return &f;
  return nullptr;
}

std::string export_format_names(const std::string& last) {
  const auto& formats = export_formats();
  std::string s;
  for (std::size_t k = 0; k < formats.size(); ++k) {
    if (k > 0) s += k + 1 == formats.size() ? last : ", ";
    s += formats[k].name;
  }
  return s;
}

}  // namespace clumpkit
