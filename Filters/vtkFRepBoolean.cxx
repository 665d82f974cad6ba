#include "vtkFRepBoolean.h"

#include "vtkAlgorithmOutput.h"
#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "Compiler/combine.h"

#include <algorithm>
#include <array>
#include <exception>
#include <limits>
#include <set>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkFRepBoolean);

namespace
{
frep::Operation EngineOperation(int operation)
{
  switch (operation)
  {
    case vtkFRepBoolean::VTK_INTERSECTION:
      return frep::Operation::Intersection;
    case vtkFRepBoolean::VTK_DIFFERENCE:
      return frep::Operation::Difference;
    case vtkFRepBoolean::VTK_BLEND_UNION:
      return frep::Operation::BlendUnion;
    case vtkFRepBoolean::VTK_BLEND_INTERSECTION:
      return frep::Operation::BlendIntersection;
    case vtkFRepBoolean::VTK_CARTESIAN_PRODUCT:
      return frep::Operation::CartesianProduct;
    default:
      return frep::Operation::Union;
  }
}

// "3 free coordinates (x1, x2, x3) of ball" for error messages.
std::string Describe(vtkFRepObject* object)
{
  std::ostringstream os;
  os << object->GetDimension() << " free coordinate" << (object->GetDimension() == 1 ? "" : "s")
     << " (";
  for (int axis = 0; axis < object->GetDimension(); ++axis)
  {
    os << (axis ? ", " : "") << object->GetCoordinateName(object->GetFreeCoordinate(axis));
  }
  os << ") of " << object->GetObjectName();
  return os.str();
}
}

//------------------------------------------------------------------------------
vtkFRepBoolean::vtkFRepBoolean()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkFRepBoolean::~vtkFRepBoolean() = default;

//------------------------------------------------------------------------------
const char* vtkFRepBoolean::GetOperationAsString() const
{
  switch (this->Operation)
  {
    case VTK_INTERSECTION:
      return "Intersection";
    case VTK_DIFFERENCE:
      return "Difference";
    case VTK_BLEND_UNION:
      return "BlendUnion";
    case VTK_BLEND_INTERSECTION:
      return "BlendIntersection";
    case VTK_CARTESIAN_PRODUCT:
      return "CartesianProduct";
    default:
      return "Union";
  }
}

//------------------------------------------------------------------------------
void vtkFRepBoolean::SetSourceConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkFRepBoolean::SetSourceData(vtkDataObject* b)
{
  this->SetInputDataObject(1, b);
}

//------------------------------------------------------------------------------
int vtkFRepBoolean::RequestInformation(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  // The output's metadata from the operands' keys (nothing upstream is executed): every
  // coordinate free, names and intervals as CopyCoordinates gives them. Operands that cannot be
  // combined publish no object; RequestData reports why, once.
  vtkFRepInformation::Metadata a;
  vtkFRepInformation::Metadata b;
  if (!vtkFRepInformation::Get(inInfo[0]->GetInformationObject(0), a) ||
    !vtkFRepInformation::Get(inInfo[1]->GetInformationObject(0), b) ||
    (this->Operation != VTK_CARTESIAN_PRODUCT && a.GetDimension() != b.GetDimension()))
  {
    return 1;
  }
  vtkFRepInformation::Metadata output;
  output.ObjectName = std::string(frep::operation_name(EngineOperation(this->Operation))) + "(" +
    a.ObjectName + ", " + b.ObjectName + ")";
  this->CombineCoordinates(a, b, output);
  vtkFRepInformation::Set(outInfo->GetInformationObject(0), output);
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepBoolean::RequestData(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  vtkFRepObject* output = vtkFRepObject::GetData(outInfo);
  if (!output)
  {
    vtkErrorMacro(<< "the output is not a vtkFRepObject");
    return 0;
  }
  output->Initialize();
  vtkFRepObject* inputs[2] = { vtkFRepObject::GetData(inInfo[0]),
    vtkFRepObject::GetData(inInfo[1]) };
  for (int port = 0; port < 2; ++port)
  {
    if (!inputs[port] || !inputs[port]->HasModel())
    {
      vtkErrorMacro(<< this->GetOperationAsString() << ": operand " << (port == 0 ? "A" : "B")
                    << " (input port " << port
                    << ") is an empty FRep object (no model); the output is empty");
      return 1;
    }
  }
  vtkFRepObject* a = inputs[0];
  vtkFRepObject* b = inputs[1];
  if (this->Operation != VTK_CARTESIAN_PRODUCT && a->GetDimension() != b->GetDimension())
  {
    vtkErrorMacro(<< this->GetOperationAsString()
                  << ": the operands must have the same dimension, but A has " << Describe(a)
                  << " and B has " << Describe(b)
                  << " (fix coordinates with vtkFRepSlice, or use CartesianProduct); the output "
                     "is empty");
    return 1;
  }

  frep::OperationParameters parameters;
  parameters.a0 = this->BlendDisplacement;
  parameters.a1 = this->BlendParameters[0];
  parameters.a2 = this->BlendParameters[1];
  frep::CombineResult combined;
  try
  {
    combined = frep::combine(EngineOperation(this->Operation),
      frep::Operand{ a->GetModel(), a->GetSpecialisation() },
      frep::Operand{ b->GetModel(), b->GetSpecialisation() },
      parameters);
  }
  catch (const std::exception& e)
  {
    // Bad operands are error values; an exception here is an engine bug or exhausted memory,
    // which must not take the pipeline down either.
    combined.error = std::string("combining the operands failed: ") + e.what();
  }
  if (!combined.ok())
  {
    vtkErrorMacro(<< combined.error << "; the output is empty");
    return 1;
  }
  output->SetModel(combined.model);
  vtkFRepInformation::Metadata described[2];
  vtkFRepInformation::Describe(a, described[0]);
  vtkFRepInformation::Describe(b, described[1]);
  vtkFRepInformation::Metadata coordinates;
  this->CombineCoordinates(described[0], described[1], coordinates);
  for (int i = 0; i < output->GetModelDimension() && i < coordinates.GetModelDimension(); ++i)
  {
    output->SetCoordinateName(i, coordinates.Names[i]);
    output->SetCoordinateRange(i, coordinates.Ranges[i][0], coordinates.Ranges[i][1]);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkFRepBoolean::CombineCoordinates(const vtkFRepInformation::Metadata& a,
  const vtkFRepInformation::Metadata& b,
  vtkFRepInformation::Metadata& output) const
{
  const bool product = this->Operation == VTK_CARTESIAN_PRODUCT;
  const int dimension = product ? a.GetDimension() + b.GetDimension() : a.GetDimension();
  std::set<std::string> taken;
  output.Names.clear();
  output.Ranges.clear();
  output.FixedValues.assign(dimension, std::numeric_limits<double>::quiet_NaN());
  output.FreeCoordinates.clear();
  output.Parameters.clear();
  for (int i = 0; i < dimension; ++i)
  {
    // The input and its axis this coordinate comes from.
    const vtkFRepInformation::Metadata& from = product && i >= a.GetDimension() ? b : a;
    const int axis = &from == &b ? i - a.GetDimension() : i;
    const int coordinate = from.FreeCoordinates[axis];
    std::array<double, 2> range = from.Ranges[coordinate];
    if (!product)
    {
      const std::array<double, 2>& other = b.Ranges[b.FreeCoordinates[axis]];
      range[0] = std::min(range[0], other[0]);
      range[1] = std::max(range[1], other[1]);
    }
    std::string name = from.Names[coordinate];
    if (taken.count(name))
    {
      name = "x" + std::to_string(i + 1);
      while (taken.count(name))
      {
        name += "'";
      }
    }
    taken.insert(name);
    output.Names.push_back(name);
    output.Ranges.push_back(range);
    output.FreeCoordinates.push_back(i);
  }
}

//------------------------------------------------------------------------------
void vtkFRepBoolean::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Operation: " << this->GetOperationAsString() << "\n";
  os << indent << "BlendDisplacement: " << this->BlendDisplacement << "\n";
  os << indent << "BlendParameters: (" << this->BlendParameters[0] << ", "
     << this->BlendParameters[1] << ")\n";
}
