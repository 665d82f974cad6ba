#include "vtkImageDataToFRep.h"

#include "vtkAlgorithm.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "Shapes/shape_functions.h"
#include "Shapes/volume_field.h"

vtkStandardNewMacro(vtkImageDataToFRep);

//------------------------------------------------------------------------------
vtkImageDataToFRep::vtkImageDataToFRep()
{
  this->SetNumberOfInputPorts(1);
}

//------------------------------------------------------------------------------
vtkImageDataToFRep::~vtkImageDataToFRep() = default;

//------------------------------------------------------------------------------
int vtkImageDataToFRep::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkImageDataToFRep::InformationBounds(vtkInformationVector** inputVector, double b[6])
{
  // An image's geometry is in its information: no need to execute upstream.
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  if (!in || !in->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    return false;
  }
  int extent[6];
  in->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  double origin[3] = { 0, 0, 0 };
  double spacing[3] = { 1, 1, 1 };
  if (in->Has(vtkDataObject::ORIGIN()))
  {
    in->Get(vtkDataObject::ORIGIN(), origin);
  }
  if (in->Has(vtkDataObject::SPACING()))
  {
    in->Get(vtkDataObject::SPACING(), spacing);
  }
  for (int k = 0; k < 3; ++k)
  {
    if (extent[2 * k] > extent[2 * k + 1])
    {
      return false;
    }
    b[2 * k] = origin[k] + spacing[k] * extent[2 * k];
    b[2 * k + 1] = origin[k] + spacing[k] * extent[2 * k + 1];
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkImageDataToFRep::MakeFunction(vtkInformationVector** inputVector,
  frep::UserFunction& function, double b[6], bool& haveBounds)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  if (!input)
  {
    vtkErrorMacro(<< "no input image");
    return false;
  }
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  if (!scalars && input->GetPointData()->GetNumberOfArrays() > 0)
  {
    scalars = input->GetPointData()->GetArray(0);
  }
  if (!scalars || scalars->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    vtkErrorMacro(<< "the volume has no point scalars (nothing to make a field from)");
    return false;
  }
  frep::shapes::VolumeGrid grid;
  int dims[3];
  input->GetDimensions(dims);
  const double* spacing = input->GetSpacing();
  double corner[3];
  input->GetPoint(0, corner); // the origin moved by the extent's start
  for (int k = 0; k < 3; ++k)
  {
    grid.dims[k] = dims[k];
    grid.spacing[k] = spacing[k];
    grid.origin[k] = corner[k];
  }
  if (input->GetDirectionMatrix() && !input->GetDirectionMatrix()->IsIdentity())
  {
    vtkErrorMacro(<< "images with a direction matrix other than the identity are not read");
    return false;
  }
  grid.values.resize(static_cast<std::size_t>(scalars->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    grid.values[static_cast<std::size_t>(i)] = scalars->GetComponent(i, 0);
  }
  if (this->CheckAbort())
  {
    return false;
  }
  auto built = frep::shapes::VolumeField::build(std::move(grid), this->IsoValue);
  if (!built.field)
  {
    vtkErrorMacro(<< built.error);
    return false;
  }
  const std::array<double, 6> bounds = built.field->bounds();
  for (int k = 0; k < 3; ++k)
  {
    b[2 * k] = bounds[k];
    b[2 * k + 1] = bounds[k + 3];
  }
  haveBounds = true;
  function = frep::shapes::volume_function(this->FunctionName ? this->FunctionName : "", built.field);
  return true;
}

//------------------------------------------------------------------------------
void vtkImageDataToFRep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IsoValue: " << this->IsoValue << "\n";
}
