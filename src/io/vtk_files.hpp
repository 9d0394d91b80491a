#pragma once
// VTK files through VTK itself (issue 21): the engines' legacy particle and wall dumps are read
// with VTK's legacy reader, and everything the workbench writes for ParaView is VTK XML (.vtp
// polydata, .vti image data) from VTK's XML writers, indexed by .pvd time collections. ParaView's
// PVD reader takes only XML datasets: a .pvd over legacy .vtk files does not open (issue 21).
// Writes are atomic: each file is written to a string and renamed into place.
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace iwb::io {

// values[i * components + c] for point (or cell) i.
struct VtkArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

struct PointCloud {
  std::vector<Eigen::Vector3d> points;
  std::vector<VtkArray> arrays;                         // per point
  const VtkArray* find(const std::string& name) const;  // nullptr if absent
};

// Line segments, each with per-segment (cell) arrays: contacts as branch vectors.
struct Segments {
  std::vector<Eigen::Vector3d> from, to;
  std::vector<VtkArray> arrays;  // per segment
  const VtkArray* find(const std::string& name) const;
};

// Values on a regular grid, x fastest (VTK's ImageData order).
struct ImageGrid {
  int nx = 1, ny = 1, nz = 1;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), spacing = Eigen::Vector3d::Ones();
  std::vector<VtkArray> arrays;  // per point
};

// The points and point arrays of any VTK dataset with points (legacy .vtk of any version VTK 9.1
// reads, or .vtp); InputError naming the file if it cannot be read.
PointCloud read_points(const std::filesystem::path& path);
void write_points(const std::filesystem::path& vtp, const PointCloud& cloud);
Segments read_segments(const std::filesystem::path& vtp);
void write_segments(const std::filesystem::path& vtp, const Segments& segments);
// Any legacy dataset (a wall mesh) as polydata, shifted by `shift`.
void convert_to_polydata(const std::filesystem::path& legacy, const std::filesystem::path& vtp,
                         const Eigen::Vector3d& shift = Eigen::Vector3d::Zero());
void write_image(const std::filesystem::path& vti, const ImageGrid& image);
ImageGrid read_image(const std::filesystem::path& vti);

struct TimedFile {
  double time;
  std::string file;  // relative to the .pvd
};
// A ParaView collection (VTK has no PVD writer; the format is ParaView's, a list of DataSet tags).
void write_collection(const std::filesystem::path& pvd, const std::vector<TimedFile>& files);

}  // namespace iwb::io
