#include "vtkImplicitFunctionToFRep.h"

#include "vtkImplicitFunction.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"

#include "Shapes/shape_functions.h"

#include <mutex>

vtkStandardNewMacro(vtkImplicitFunctionToFRep);
vtkCxxSetObjectMacro(vtkImplicitFunctionToFRep, ImplicitFunction, vtkImplicitFunction);

//------------------------------------------------------------------------------
vtkImplicitFunctionToFRep::vtkImplicitFunctionToFRep()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkImplicitFunctionToFRep::~vtkImplicitFunctionToFRep()
{
  this->SetImplicitFunction(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkImplicitFunctionToFRep::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->ImplicitFunction)
  {
    t = std::max(t, this->ImplicitFunction->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
bool vtkImplicitFunctionToFRep::MakeFunction(
  vtkInformationVector**, frep::UserFunction& function, double*, bool& haveBounds)
{
  if (!this->ImplicitFunction)
  {
    vtkErrorMacro(<< "no ImplicitFunction is set");
    return false;
  }
  haveBounds = false;
  // The object keeps the function alive as long as the model exists (the tape holds it).
  vtkSmartPointer<vtkImplicitFunction> f = this->ImplicitFunction;
  std::shared_ptr<std::mutex> lock =
    this->SerializeEvaluation ? std::make_shared<std::mutex>() : nullptr;
  function = frep::shapes::point_function(this->FunctionName ? this->FunctionName : "",
    [f, lock](const std::array<double, 3>& p)
    {
      double x[3] = { p[0], p[1], p[2] };
      if (lock)
      {
        std::lock_guard<std::mutex> guard(*lock);
        return -f->FunctionValue(x);
      }
      return -f->FunctionValue(x);
    });
  return true;
}

//------------------------------------------------------------------------------
void vtkImplicitFunctionToFRep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ImplicitFunction: " << this->ImplicitFunction << "\n";
  os << indent << "SerializeEvaluation: " << (this->SerializeEvaluation ? "on" : "off") << "\n";
}
