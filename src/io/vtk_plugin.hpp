#pragma once
// The table of VTK functions the module iwb_vtk_plugin exports (vtk_plugin.cpp) and vtk_files.cpp
// loads on first use, so that only a command that reads or writes a VTK file loads VTK.
#include "io/vtk_files.hpp"

namespace iwb::io {

struct VtkFunctions {
  PointCloud (*read_points)(const std::filesystem::path&);
  void (*write_points)(const std::filesystem::path&, const PointCloud&);
  Segments (*read_segments)(const std::filesystem::path&);
  void (*write_segments)(const std::filesystem::path&, const Segments&);
  void (*convert_to_polydata)(const std::filesystem::path&, const std::filesystem::path&,
                              const Eigen::Vector3d&);
  void (*write_image)(const std::filesystem::path&, const ImageGrid&);
  ImageGrid (*read_image)(const std::filesystem::path&);
};

}  // namespace iwb::io

// The module's one exported symbol.
extern "C" const iwb::io::VtkFunctions* iwb_vtk_functions();
