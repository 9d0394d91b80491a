// The VTK half of io/vtk_files.hpp, built as a module that iwb loads on first use (vtk_files.cpp):
// VTK's 20 shared libraries cost ~9 ms of start-up in every command, and most commands never
// touch a VTK file (issue 37, item 5).
#include "io/vtk_plugin.hpp"

#include <fmt/core.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkGeometryFilter.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTransform.h>
#include <vtkTransformFilter.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLWriter.h>

#include "common/errors.hpp"
#include "io/run_directory.hpp"

namespace iwb::io {

namespace fs = std::filesystem;

namespace {

std::vector<VtkArray> arrays_of(vtkFieldData* data) {
  std::vector<VtkArray> out;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = data->GetArray(i);
    if (!a || !a->GetName()) continue;  // string arrays and unnamed ones carry nothing we use
    VtkArray v{a->GetName(), a->GetNumberOfComponents(), {}};
    v.values.reserve(std::size_t(a->GetNumberOfTuples() * v.components));
    for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
      for (int c = 0; c < v.components; ++c) v.values.push_back(a->GetComponent(t, c));
    out.push_back(std::move(v));
  }
  return out;
}

void add_arrays(vtkFieldData* data, const std::vector<VtkArray>& arrays) {
  for (const auto& a : arrays) {
    vtkNew<vtkDoubleArray> d;
    d->SetName(a.name.c_str());
    d->SetNumberOfComponents(a.components);
    d->SetNumberOfTuples(vtkIdType(a.values.size() / std::size_t(a.components)));
    for (std::size_t i = 0; i < a.values.size(); ++i) d->SetValue(vtkIdType(i), a.values[i]);
    data->AddArray(d);
  }
}

// VTK writers report failures through their error code, not exceptions.
template <class Writer>
void write_through(Writer* writer, const fs::path& path) {
  writer->SetDataModeToAppended();
  writer->SetCompressorTypeToZLib();
  writer->WriteToOutputStringOn();
  if (writer->Write() != 1)
    throw std::runtime_error(fmt::format("{}: VTK could not write the dataset", path.string()));
  write_atomically(path, writer->GetOutputString());
}

vtkSmartPointer<vtkDataObject> read_any(const fs::path& path) {
  if (!fs::exists(path)) throw InputError(fmt::format("{}: no such file", path.string()));
  if (path.extension() == ".vtp") {
    vtkNew<vtkXMLPolyDataReader> r;
    r->SetFileName(path.c_str());
    r->Update();
    if (r->GetErrorCode() != 0 || !r->GetOutput())
      throw InputError(fmt::format("{}: not a VTK XML polydata file", path.string()));
    return r->GetOutput();
  }
  vtkNew<vtkGenericDataObjectReader> r;
  r->SetFileName(path.c_str());
  // a legacy file's second SCALARS or VECTORS is dropped unless asked for (YADE writes several)
  r->ReadAllScalarsOn();
  r->ReadAllVectorsOn();
  r->ReadAllFieldsOn();
  r->Update();
  if (r->GetErrorCode() != 0 || !r->GetOutput())
    throw InputError(fmt::format("{}: not a legacy VTK file VTK can read", path.string()));
  return r->GetOutput();
}

// The module's functions have internal linkage: the executable's forwarders of the same names
// (vtk_files.cpp) must never be what the table points to.
PointCloud read_points(const fs::path& path) {
  auto data = read_any(path);
  auto* set = vtkPointSet::SafeDownCast(data);
  if (!set || !set->GetPoints())
    throw InputError(fmt::format("{}: holds no points", path.string()));
  PointCloud cloud;
  for (vtkIdType i = 0; i < set->GetNumberOfPoints(); ++i) {
    double p[3];
    set->GetPoint(i, p);
    cloud.points.emplace_back(p[0], p[1], p[2]);
  }
  cloud.arrays = arrays_of(set->GetPointData());
  return cloud;
}

// Points with one vertex cell each, so that ParaView draws them without a Glyph first.
void write_points(const fs::path& vtp, const PointCloud& cloud) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> vertices;
  for (const auto& p : cloud.points) {
    const vtkIdType id = points->InsertNextPoint(p.x(), p.y(), p.z());
    vertices->InsertNextCell(1, &id);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetVerts(vertices);
  add_arrays(poly->GetPointData(), cloud.arrays);
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(poly);
  write_through(w.GetPointer(), vtp);
}

Segments read_segments(const fs::path& vtp) {
  const auto data = read_any(vtp);  // holds the dataset while it is read
  auto* poly = vtkPolyData::SafeDownCast(data);
  if (!poly) throw InputError(fmt::format("{}: not polydata", vtp.string()));
  Segments s;
  vtkCellArray* lines = poly->GetLines();
  lines->InitTraversal();
  vtkNew<vtkIdList> ids;
  while (lines->GetNextCell(ids)) {
    if (ids->GetNumberOfIds() != 2)
      throw InputError(fmt::format("{}: a line that is not a segment", vtp.string()));
    double a[3], b[3];
    poly->GetPoint(ids->GetId(0), a);
    poly->GetPoint(ids->GetId(1), b);
    s.from.emplace_back(a[0], a[1], a[2]);
    s.to.emplace_back(b[0], b[1], b[2]);
  }
  s.arrays = arrays_of(poly->GetCellData());
  return s;
}

void write_segments(const fs::path& vtp, const Segments& segments) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  for (std::size_t i = 0; i < segments.from.size(); ++i) {
    const vtkIdType ids[2] = {points->InsertNextPoint(segments.from[i].data()),
                              points->InsertNextPoint(segments.to[i].data())};
    lines->InsertNextCell(2, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  add_arrays(poly->GetCellData(), segments.arrays);
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(poly);
  write_through(w.GetPointer(), vtp);
}

void convert_to_polydata(const fs::path& legacy, const fs::path& vtp,
                         const Eigen::Vector3d& shift) {
  auto data = read_any(legacy);
  vtkNew<vtkGeometryFilter> surface;
  surface->SetInputData(data);
  vtkNew<vtkTransform> move;
  move->Translate(shift.data());
  vtkNew<vtkTransformFilter> moved;
  moved->SetTransform(move);
  moved->SetInputConnection(surface->GetOutputPort());
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputConnection(moved->GetOutputPort());
  write_through(w.GetPointer(), vtp);
}

void write_image(const fs::path& vti, const ImageGrid& image) {
  vtkNew<vtkImageData> grid;
  grid->SetDimensions(image.nx, image.ny, image.nz);
  grid->SetOrigin(image.origin.data());
  grid->SetSpacing(image.spacing.data());
  add_arrays(grid->GetPointData(), image.arrays);
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(grid);
  write_through(w.GetPointer(), vti);
}

ImageGrid read_image(const fs::path& vti) {
  if (!fs::exists(vti)) throw InputError(fmt::format("{}: no such file", vti.string()));
  vtkNew<vtkXMLImageDataReader> r;
  r->SetFileName(vti.c_str());
  r->Update();
  vtkImageData* grid = r->GetOutput();
  if (r->GetErrorCode() != 0 || !grid)
    throw InputError(fmt::format("{}: not a VTK XML image data file", vti.string()));
  ImageGrid im;
  int dims[3];
  grid->GetDimensions(dims);
  im.nx = dims[0], im.ny = dims[1], im.nz = dims[2];
  grid->GetOrigin(im.origin.data());
  grid->GetSpacing(im.spacing.data());
  im.arrays = arrays_of(grid->GetPointData());
  return im;
}

const VtkFunctions kFunctions{read_points,         write_points, read_segments, write_segments,
                              convert_to_polydata, write_image,  read_image};

}  // namespace
}  // namespace iwb::io

extern "C" __attribute__((visibility("default"))) const iwb::io::VtkFunctions* iwb_vtk_functions() {
  return &iwb::io::kFunctions;
}
