#include "io/vtk_files.hpp"

#include <dlfcn.h>
#include <fmt/core.h>

#include <stdexcept>

#include "io/run_directory.hpp"
#include "io/vtk_plugin.hpp"

namespace iwb::io {

namespace fs = std::filesystem;

namespace {

const VtkArray* find_in(const std::vector<VtkArray>& arrays, const std::string& name) {
  for (const auto& a : arrays)
    if (a.name == name) return &a;
  return nullptr;
}

// Where the module is: beside an installed iwb (bin/../lib/.../iwb/, IWB_VTK_MODULE_FROM_BINDIR),
// else where the build put it. The installed place comes first, so that an installed iwb never
// runs on a build tree's module that happens to still exist.
std::vector<fs::path> module_candidates() {
  std::vector<fs::path> out;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) out.push_back(exe.parent_path() / IWB_VTK_MODULE_FROM_BINDIR / IWB_VTK_MODULE_NAME);
  out.emplace_back(IWB_VTK_MODULE_BUILD_PATH);
  return out;
}

const VtkFunctions& load_module() {
  std::string tried;
  for (const auto& path : module_candidates()) {
    // RTLD_LOCAL: VTK's symbols stay the module's own; loaded once, never unloaded
    if (void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
      using Entry = const VtkFunctions* (*)();
      if (auto entry = reinterpret_cast<Entry>(dlsym(handle, "iwb_vtk_functions"))) return *entry();
      tried += fmt::format("; {}: no iwb_vtk_functions", path.string());
      continue;
    }
    tried += fmt::format("; {}", dlerror());
  }
  throw std::runtime_error(
      fmt::format("VTK files need iwb's module {}, which did not load{} (reinstall iwb, or "
                  "rebuild it)",
                  IWB_VTK_MODULE_NAME, tried));
}

const VtkFunctions& vtk() {
  static const VtkFunctions& functions = load_module();  // thread-safe, once; a failure retries
  return functions;
}

}  // namespace

const VtkArray* PointCloud::find(const std::string& name) const {
  return find_in(arrays, name);
}
const VtkArray* Segments::find(const std::string& name) const {
  return find_in(arrays, name);
}

PointCloud read_points(const fs::path& path) {
  return vtk().read_points(path);
}
void write_points(const fs::path& vtp, const PointCloud& cloud) {
  vtk().write_points(vtp, cloud);
}
Segments read_segments(const fs::path& vtp) {
  return vtk().read_segments(vtp);
}
void write_segments(const fs::path& vtp, const Segments& segments) {
  vtk().write_segments(vtp, segments);
}
void convert_to_polydata(const fs::path& legacy, const fs::path& vtp,
                         const Eigen::Vector3d& shift) {
  vtk().convert_to_polydata(legacy, vtp, shift);
}
void write_image(const fs::path& vti, const ImageGrid& image) {
  vtk().write_image(vti, image);
}
ImageGrid read_image(const fs::path& vti) {
  return vtk().read_image(vti);
}

// ParaView's collection is plain XML: no VTK needed.
void write_collection(const fs::path& pvd, const std::vector<TimedFile>& files) {
  std::string xml =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& f : files)
    xml += fmt::format("  <DataSet timestep=\"{:.10g}\" file=\"{}\"/>\n", f.time, f.file);
  xml += "</Collection>\n</VTKFile>\n";
  write_atomically(pvd, xml);
}

}  // namespace iwb::io
