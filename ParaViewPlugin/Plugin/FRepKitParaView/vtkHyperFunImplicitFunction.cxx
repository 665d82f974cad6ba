#include "vtkHyperFunImplicitFunction.h"

#include "vtkFRepObject.h"
#include "vtkHyperFunSource.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkHyperFunImplicitFunction);

//------------------------------------------------------------------------------
vtkHyperFunImplicitFunction::vtkHyperFunImplicitFunction() = default;

//------------------------------------------------------------------------------
vtkHyperFunImplicitFunction::~vtkHyperFunImplicitFunction() = default;

//------------------------------------------------------------------------------
void vtkHyperFunImplicitFunction::RequestChanged()
{
  ++this->Requested;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkHyperFunImplicitFunction::SetFileName(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->FileName)
  {
    this->FileName = value;
    this->RequestChanged();
  }
}

//------------------------------------------------------------------------------
void vtkHyperFunImplicitFunction::SetModelText(const char* text)
{
  const std::string value = text ? text : "";
  if (value != this->ModelText)
  {
    this->ModelText = value;
    this->RequestChanged();
  }
}

//------------------------------------------------------------------------------
void vtkHyperFunImplicitFunction::SetObjectName(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->HyperFunObject)
  {
    this->HyperFunObject = value;
    this->RequestChanged();
  }
}

//------------------------------------------------------------------------------
void vtkHyperFunImplicitFunction::SetExtraCoordinate(int i, double value)
{
  if (i < 0 || i >= NumberOfExtraCoordinates)
  {
    vtkErrorMacro(<< "SetExtraCoordinate: index " << i << " is not in 0.."
                  << NumberOfExtraCoordinates - 1 << " (x4..x8)");
    return;
  }
  if (this->ExtraCoordinates[i] != value)
  {
    this->ExtraCoordinates[i] = value;
    this->RequestChanged();
  }
}

//------------------------------------------------------------------------------
double vtkHyperFunImplicitFunction::GetExtraCoordinate(int i) const
{
  return i >= 0 && i < NumberOfExtraCoordinates ? this->ExtraCoordinates[i] : 0.0;
}

//------------------------------------------------------------------------------
void vtkHyperFunImplicitFunction::Reload()
{
  this->Source->Modified();
  this->RequestChanged();
}

//------------------------------------------------------------------------------
void vtkHyperFunImplicitFunction::Prepare()
{
  const unsigned long requested = this->Requested.load();
  if (this->Built.load() == requested)
  {
    return;
  }
  std::lock_guard<std::mutex> lock(this->BuildMutex);
  if (this->Built.load() == requested)
  {
    return;
  }
  this->Source->SetFileName(this->FileName.empty() ? nullptr : this->FileName.c_str());
  this->Source->SetModelText(this->ModelText.empty() ? nullptr : this->ModelText.c_str());
  this->Source->SetObjectName(this->HyperFunObject.empty() ? nullptr : this->HyperFunObject.c_str());
  vtkFRepObject* object = nullptr;
  vtkNew<vtkFRepObject> section;
  if (!this->FileName.empty() || !this->ModelText.empty())
  {
    this->Source->Update();
    if (this->Source->GetOutput()->HasModel())
    {
      section->ShallowCopy(this->Source->GetOutput());
      for (int c = 3; c < section->GetModelDimension(); ++c)
      {
        double range[2];
        section->GetCoordinateRange(c, range);
        const int extra = c - 3;
        section->FixCoordinate(c,
          extra < NumberOfExtraCoordinates ? this->ExtraCoordinates[extra]
                                           : 0.5 * (range[0] + range[1]));
      }
      object = section;
    }
  }
  this->SetFRepObject(object);
  this->Built.store(requested);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkHyperFunImplicitFunction::GetMTime()
{
  this->Prepare();
  return this->Superclass::GetMTime();
}

//------------------------------------------------------------------------------
double vtkHyperFunImplicitFunction::EvaluateFunction(double x[3])
{
  this->Prepare();
  return this->Superclass::EvaluateFunction(x);
}

//------------------------------------------------------------------------------
void vtkHyperFunImplicitFunction::EvaluateFunction(vtkDataArray* input, vtkDataArray* output)
{
  this->Prepare();
  this->Superclass::EvaluateFunction(input, output);
}

//------------------------------------------------------------------------------
void vtkHyperFunImplicitFunction::EvaluateGradient(double x[3], double g[3])
{
  this->Prepare();
  this->Superclass::EvaluateGradient(x, g);
}

//------------------------------------------------------------------------------
void vtkHyperFunImplicitFunction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName.empty() ? "(none)" : this->FileName) << "\n";
  os << indent << "ModelText: " << (this->ModelText.empty() ? "(none)" : "set") << "\n";
  os << indent << "ObjectName: " << (this->HyperFunObject.empty() ? "(none)" : this->HyperFunObject)
     << "\n";
  os << indent << "ExtraCoordinates:";
  for (double v : this->ExtraCoordinates)
  {
    os << " " << v;
  }
  os << "\n";
}
