#include "vtkPolyDataToFRep.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include "Shapes/mesh_distance.h"
#include "Shapes/shape_functions.h"

vtkStandardNewMacro(vtkPolyDataToFRep);

//------------------------------------------------------------------------------
vtkPolyDataToFRep::vtkPolyDataToFRep()
{
  this->SetNumberOfInputPorts(1);
}

//------------------------------------------------------------------------------
vtkPolyDataToFRep::~vtkPolyDataToFRep() = default;

//------------------------------------------------------------------------------
int vtkPolyDataToFRep::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkPolyDataToFRep::InformationBounds(vtkInformationVector** inputVector, double b[6])
{
  // Given as data (or executed before), the mesh is already there.
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return false;
  }
  input->GetBounds(b);
  return true;
}

//------------------------------------------------------------------------------
bool vtkPolyDataToFRep::MakeFunction(vtkInformationVector** inputVector,
  frep::UserFunction& function, double b[6], bool& haveBounds)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  if (!input || input->GetNumberOfPoints() == 0 || input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro(<< "the input has no polygons");
    return false;
  }
  if (input->GetNumberOfStrips() > 0 || input->GetNumberOfLines() > 0 ||
    input->GetNumberOfVerts() > 0)
  {
    vtkErrorMacro(<< "the input has strips, lines or vertices: only polygons are read "
                     "(vtkTriangleFilter turns strips into triangles)");
    return false;
  }
  frep::shapes::TriangleMesh mesh;
  mesh.points.resize(static_cast<std::size_t>(3 * input->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    input->GetPoint(i, &mesh.points[static_cast<std::size_t>(3 * i)]);
  }
  vtkCellArray* polys = input->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 1; k + 1 < n; ++k)
    {
      mesh.triangles.insert(mesh.triangles.end(), { static_cast<std::uint32_t>(ids[0]),
        static_cast<std::uint32_t>(ids[k]), static_cast<std::uint32_t>(ids[k + 1]) });
    }
  }
  if (this->CheckAbort())
  {
    return false;
  }
  auto built = frep::shapes::MeshDistance::build(std::move(mesh), !this->UnsignedDistance);
  if (!built.distance)
  {
    vtkErrorMacro(<< built.error);
    return false;
  }
  input->GetBounds(b);
  haveBounds = true;
  function = frep::shapes::mesh_function(this->FunctionName ? this->FunctionName : "", built.distance);
  return true;
}

//------------------------------------------------------------------------------
void vtkPolyDataToFRep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UnsignedDistance: " << (this->UnsignedDistance ? "on" : "off") << "\n";
}
