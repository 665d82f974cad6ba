#include "SectionMeshConversion.h"

#include "vtkFRepPolygonizer.h"

#include "Compiler/attribute_rgb.h"

#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>

namespace frepstudio
{

SectionColouring colouring_for(const frep::Tape& tape, int s_dim)
{
  if (frep::tape_sets_colours(tape, s_dim))
    return SectionColouring::Rgb;
  if (s_dim >= 1 && frep::tape_sets_attributes(tape, 1))
    return SectionColouring::Attribute;
  return SectionColouring::Plain;
}

vtkSmartPointer<vtkPolyData> to_poly_data(const frep::mesh::Surface& surface,
  SectionColouring colouring)
{
  // Points (double, as the engine computes them), cells and normals as the polygoniser gives them.
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkFRepPolygonizer::ConvertSurface(surface, vtkAlgorithm::DOUBLE_PRECISION, poly);
  const vtkIdType point_count = static_cast<vtkIdType>(surface.point_count());

  if (colouring == SectionColouring::Rgb)
  {
    const std::vector<frep::AttributeRgb> colours = frep::attribute_colours(
      surface.attributes, static_cast<std::size_t>(surface.attribute_count), surface.point_count());
    if (static_cast<vtkIdType>(colours.size()) == point_count)
    {
      vtkNew<vtkUnsignedCharArray> rgb;
      rgb->SetName("Colors");
      rgb->SetNumberOfComponents(3);
      rgb->SetNumberOfTuples(point_count);
      for (vtkIdType i = 0; i < point_count; ++i)
        for (int c = 0; c < 3; ++c)
          rgb->SetTypedComponent(i, c, frep::colour_byte(colours[i][c]));
      poly->GetPointData()->SetScalars(rgb);
    }
  }
  else if (colouring == SectionColouring::Attribute && surface.attribute_count >= 1 &&
           surface.attributes.size() ==
             static_cast<std::size_t>(point_count) * surface.attribute_count)
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
