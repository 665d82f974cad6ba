#include "vtkFRepShapeAlgorithm.h"

#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"

#include "Compiler/load_model.h"
#include "Shapes/shape_functions.h"

#include <cmath>

vtkStandardNewMacro(vtkFRepShapeAlgorithm);

//------------------------------------------------------------------------------
vtkFRepShapeAlgorithm::vtkFRepShapeAlgorithm()
{
  this->SetNumberOfInputPorts(0);
  this->SetFunctionName("shape");
}

//------------------------------------------------------------------------------
bool vtkFRepShapeAlgorithm::MakeFunction(vtkInformationVector**, frep::UserFunction&, double*, bool&)
{
  vtkErrorMacro(<< "vtkFRepShapeAlgorithm makes no function itself: use vtkPolyDataToFRep, "
                   "vtkImageDataToFRep or vtkImplicitFunctionToFRep");
  return false;
}

//------------------------------------------------------------------------------
vtkFRepShapeAlgorithm::~vtkFRepShapeAlgorithm()
{
  this->SetFunctionName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkFRepShapeAlgorithm::InformationBounds(vtkInformationVector**, double*)
{
  return false;
}

//------------------------------------------------------------------------------
void vtkFRepShapeAlgorithm::Ranges(const double b[6], bool haveBounds, double ranges[6]) const
{
  if (this->Bounds[0] <= this->Bounds[1] && this->Bounds[2] <= this->Bounds[3] &&
    this->Bounds[4] <= this->Bounds[5])
  {
    std::copy(this->Bounds, this->Bounds + 6, ranges);
    return;
  }
  if (!haveBounds)
  {
    for (int k = 0; k < 3; ++k)
    {
      ranges[2 * k] = -10;
      ranges[2 * k + 1] = 10;
    }
    return;
  }
  const double diagonal =
    std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  const double pad = std::max(this->Padding * diagonal, 1e-6);
  for (int k = 0; k < 3; ++k)
  {
    ranges[2 * k] = b[2 * k] - pad;
    ranges[2 * k + 1] = b[2 * k + 1] + pad;
  }
}

//------------------------------------------------------------------------------
int vtkFRepShapeAlgorithm::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outInfo)
{
  double b[6] = { 0, 0, 0, 0, 0, 0 };
  const bool have = this->InformationBounds(inputVector, b);
  double ranges[6];
  this->Ranges(b, have, ranges);
  vtkFRepInformation::Metadata m;
  const std::string name = this->FunctionName ? this->FunctionName : "";
  m.ObjectName = name + "_model";
  for (int k = 0; k < 3; ++k)
  {
    m.Names.push_back("x" + std::to_string(k + 1));
    m.Ranges.push_back({ ranges[2 * k], ranges[2 * k + 1] });
    m.FixedValues.push_back(NAN);
    m.FreeCoordinates.push_back(k);
  }
  vtkFRepInformation::Set(outInfo->GetInformationObject(0), m);
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepShapeAlgorithm::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outInfo)
{
  vtkFRepObject* output = vtkFRepObject::GetData(outInfo);
  if (!output)
  {
    vtkErrorMacro(<< "the output is not a vtkFRepObject");
    return 0;
  }
  output->Initialize();
  const std::string name = this->FunctionName ? this->FunctionName : "";
  frep::UserFunction function;
  double b[6] = { 0, 0, 0, 0, 0, 0 };
  bool have = false;
  if (!this->MakeFunction(inputVector, function, b, have))
  {
    return 1; // reported; the output stays empty
  }
  this->UpdateProgress(0.5);
  function.name = name;
  auto registry = std::make_shared<frep::UserFunctionRegistry>();
  if (std::string e = registry->add(std::move(function)); !e.empty())
  {
    vtkErrorMacro(<< "FunctionName: " << e);
    return 1;
  }
  frep::LoadOptions options;
  options.functions = registry;
  frep::LoadedModel loaded = frep::load_model(
    frep::ModelSource::from_text(frep::shapes::wrapper_program(name), "<" + name + ">"), options);
  if (!loaded.ok())
  {
    vtkErrorMacro(<< "FunctionName '" << name << "': " << loaded.diagnostics.front().message);
    return 1;
  }
  output->SetModel(loaded.model);
  double ranges[6];
  this->Ranges(b, have, ranges);
  for (int k = 0; k < 3; ++k)
  {
    output->SetCoordinateRange(k, ranges[2 * k], ranges[2 * k + 1]);
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkFRepShapeAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FunctionName: " << (this->FunctionName ? this->FunctionName : "(none)") << "\n";
  os << indent << "Bounds: " << this->Bounds[0] << " " << this->Bounds[1] << " " << this->Bounds[2]
     << " " << this->Bounds[3] << " " << this->Bounds[4] << " " << this->Bounds[5] << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
}
