#include "vtp_writer.h"

#include "Compiler/attribute_rgb.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <string>

namespace frepkit
{

void write_vtp(const MeshDocument& mesh, std::ostream& out)
{
  const frep::mesh::Surface& surface = *mesh.surface;
  const vtkIdType point_count = static_cast<vtkIdType>(surface.point_count());

  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(point_count);
  std::copy(surface.points.begin(), surface.points.end(), coordinates->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);

  const int corners = surface.dimension == 3 ? 3 : 2;
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(
    static_cast<vtkIdType>(surface.cell_count()), static_cast<vtkIdType>(surface.cells.size()));
  vtkIdType ids[3];
  for (std::size_t c = 0; c < surface.cell_count(); ++c)
  {
    for (int k = 0; k < corners; ++k)
    {
      ids[k] = surface.cells[static_cast<std::size_t>(corners) * c + static_cast<std::size_t>(k)];
    }
    cells->InsertNextCell(corners, ids);
  }

  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  if (corners == 3)
  {
    poly->SetPolys(cells);
  }
  else
  {
    poly->SetLines(cells);
  }

  if (mesh.has_normals())
  {
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(point_count);
    std::copy(surface.normals.begin(), surface.normals.end(), normals->GetPointer(0));
    poly->GetPointData()->SetNormals(normals);
  }
  const std::size_t stride = static_cast<std::size_t>(surface.attribute_count);
  if (stride > 0 && surface.attributes.size() >= stride * surface.point_count())
  {
    for (std::size_t j = 0; j < stride; ++j)
    {
      vtkNew<vtkFloatArray> attribute;
      attribute->SetName(("s" + std::to_string(j + 1)).c_str());
      attribute->SetNumberOfTuples(point_count);
      for (vtkIdType p = 0; p < point_count; ++p)
      {
        attribute->SetValue(p, surface.attributes[static_cast<std::size_t>(p) * stride + j]);
      }
      poly->GetPointData()->AddArray(attribute);
    }
  }
  if (mesh.has_colours())
  {
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName("Colors");
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(point_count);
    for (vtkIdType p = 0; p < point_count; ++p)
    {
      for (int k = 0; k < 3; ++k)
      {
        colours->SetTypedComponent(
          p, k, frep::colour_byte(mesh.colours[static_cast<std::size_t>(p)][k]));
      }
    }
    poly->GetPointData()->SetScalars(colours);
  }

  // Written to memory, then to the caller's stream (a temporary file renamed when complete).
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(poly);
  writer->SetWriteToOutputString(true);
  writer->SetDataModeToBinary(); // inline base64: Debian 12's expat cannot read appended data back
  if (writer->Write() != 1)
  {
    throw std::runtime_error("vtkXMLPolyDataWriter failed");
  }
  out << writer->GetOutputString();
}

} // namespace frepkit
