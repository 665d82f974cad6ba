#include "SectionMeshConversion.h"

#include "mesh_writers/vertex_colours.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>

namespace frepstudio
{

SectionColouring colouring_for(const frep::Tape& tape, int s_dim)
{
  if (frepkit::tape_sets_colours(tape, s_dim))
    return SectionColouring::Rgb;
  if (s_dim >= 1 && frepkit::tape_sets_attributes(tape, 1))
    return SectionColouring::Attribute;
  return SectionColouring::Plain;
}

vtkSmartPointer<vtkPolyData> to_poly_data(const frep::mesh::Surface& surface,
  SectionColouring colouring)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  const vtkIdType point_count = static_cast<vtkIdType>(surface.point_count());

  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(point_count);
  std::copy(surface.points.begin(), surface.points.end(), coordinates->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  poly->SetPoints(points);

  // Cells as one offsets + connectivity pair: no per-cell insertion for ~10^5 triangles.
  const int per_cell = surface.dimension == 3 ? 3 : 2;
  const vtkIdType cell_count = static_cast<vtkIdType>(surface.cell_count());
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(cell_count + 1);
  for (vtkIdType i = 0; i <= cell_count; ++i)
    offsets->SetValue(i, i * per_cell);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(surface.cells.size()));
  std::copy(surface.cells.begin(), surface.cells.end(), connectivity->GetPointer(0));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  if (per_cell == 3)
    poly->SetPolys(cells);
  else
    poly->SetLines(cells);

  if (surface.normals.size() == surface.points.size() && point_count > 0)
  {
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(point_count);
    std::copy(surface.normals.begin(), surface.normals.end(), normals->GetPointer(0));
    poly->GetPointData()->SetNormals(normals);
  }

  if (colouring == SectionColouring::Rgb)
  {
    const std::vector<frepkit::Rgb> colours = frepkit::colours_from_attributes(surface);
    if (static_cast<vtkIdType>(colours.size()) == point_count)
    {
      vtkNew<vtkUnsignedCharArray> rgb;
      rgb->SetName("Colors");
      rgb->SetNumberOfComponents(3);
      rgb->SetNumberOfTuples(point_count);
      for (vtkIdType i = 0; i < point_count; ++i)
        for (int c = 0; c < 3; ++c)
          rgb->SetTypedComponent(i, c, frepkit::colour_byte(colours[i][c]));
      poly->GetPointData()->SetScalars(rgb);
    }
  }
  else if (colouring == SectionColouring::Attribute && surface.attribute_count >= 1 &&
    surface.attributes.size() == static_cast<std::size_t>(point_count) * surface.attribute_count)
  {
    vtkNew<vtkFloatArray> s1;
    s1->SetName("s1");
    s1->SetNumberOfValues(point_count);
    for (vtkIdType i = 0; i < point_count; ++i)
      s1->SetValue(i, surface.attributes[i * surface.attribute_count]);
    poly->GetPointData()->SetScalars(s1);
  }
  return poly;
}

} // namespace frepstudio
