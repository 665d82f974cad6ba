#include "vtk_shape_reader.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>

namespace frepkit
{
namespace
{

/// Runs a VTK XML reader on `path`; empty on success, else why the file is not of that `kind`.
template <class Reader>
std::string read_xml(const std::string& path, const char* kind, vtkNew<Reader>& reader)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
  {
    return path + ": cannot open the file";
  }
  if (!reader->CanReadFile(path.c_str()))
  {
    return path + ": not a VTK XML " + kind + " file";
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  return {};
}

} // namespace

bool vtk_shapes_available()
{
  return true;
}

std::string read_vtp_mesh(const std::string& path, frep::shapes::TriangleMesh& mesh)
{
  vtkNew<vtkXMLPolyDataReader> reader;
  if (std::string e = read_xml(path, "PolyData", reader); !e.empty())
  {
    return e;
  }
  vtkPolyData* poly = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || poly == nullptr || poly->GetNumberOfPoints() == 0)
  {
    return path + ": no points could be read";
  }
  mesh = {};
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    double p[3];
    poly->GetPoint(i, p);
    mesh.points.insert(mesh.points.end(), p, p + 3);
  }
  vtkCellArray* polys = poly->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 1; k + 1 < n; ++k) // a fan: polygons are convex in practice
    {
      mesh.triangles.insert(mesh.triangles.end(), { static_cast<std::uint32_t>(ids[0]),
        static_cast<std::uint32_t>(ids[k]), static_cast<std::uint32_t>(ids[k + 1]) });
    }
  }
  if (poly->GetNumberOfStrips() > 0)
  {
    return path + ": triangle strips are not read (triangulate the mesh first)";
  }
  return {};
}

std::string read_vti_volume(const std::string& path, frep::shapes::VolumeGrid& grid)
{
  vtkNew<vtkXMLImageDataReader> reader;
  if (std::string e = read_xml(path, "ImageData", reader); !e.empty())
  {
    return e;
  }
  vtkImageData* image = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || image == nullptr)
  {
    return path + ": the image could not be read";
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (scalars == nullptr && image->GetPointData()->GetNumberOfArrays() > 0)
  {
    scalars = image->GetPointData()->GetArray(0);
  }
  if (scalars == nullptr)
  {
    return path + ": the volume has no point scalars";
  }
  int dims[3];
  image->GetDimensions(dims);
  double origin[3];
  double spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  grid = {};
  for (int k = 0; k < 3; ++k)
  {
    grid.dims[k] = dims[k];
    grid.origin[k] = origin[k];
    grid.spacing[k] = spacing[k];
  }
  grid.values.resize(static_cast<std::size_t>(scalars->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    grid.values[static_cast<std::size_t>(i)] = scalars->GetComponent(i, 0);
  }
  return {};
}

} // namespace frepkit
