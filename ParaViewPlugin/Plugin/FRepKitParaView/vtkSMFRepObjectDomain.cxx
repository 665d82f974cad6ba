#include "vtkSMFRepObjectDomain.h"

#include "vtkDataObject.h"
#include "vtkObjectFactory.h"
#include "vtkPVArrayInformation.h"
#include "vtkPVDataInformation.h"
#include "vtkPVXMLElement.h"
#include "vtkSMInputProperty.h"
#include "vtkSMSourceProxy.h"
#include "vtkType.h"

#include <cmath>

vtkStandardNewMacro(vtkSMFRepObjectDomain);

//------------------------------------------------------------------------------
vtkSMFRepObjectDomain::vtkSMFRepObjectDomain() = default;

//------------------------------------------------------------------------------
vtkSMFRepObjectDomain::~vtkSMFRepObjectDomain() = default;

//------------------------------------------------------------------------------
int vtkSMFRepObjectDomain::ReadXMLAttributes(vtkSMProperty* prop, vtkPVXMLElement* element)
{
  if (!this->Superclass::ReadXMLAttributes(prop, element))
  {
    return 0;
  }
  int value = 0;
  if (element->GetScalarAttribute("minimum_dimension", &value))
  {
    this->MinimumDimension = value;
  }
  if (element->GetScalarAttribute("maximum_dimension", &value))
  {
    this->MaximumDimension = value;
  }
  if (this->MinimumDimension > this->MaximumDimension)
  {
    vtkErrorMacro(<< "minimum_dimension " << this->MinimumDimension
                  << " > maximum_dimension " << this->MaximumDimension);
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkSMFRepObjectDomain::IsInDomain(vtkPVDataInformation* information) const
{
  if (!information || information->GetDataSetType() == -1)
  {
    return 1; // not updated yet: accepted, as ParaView's own domains do
  }
  if (information->GetDataSetType() != VTK_DATA_OBJECT)
  {
    return 0;
  }
  vtkPVArrayInformation* dimension =
    information->GetArrayInformation("FRepDimension", vtkDataObject::FIELD);
  if (!dimension)
  {
    return 0; // a generic data object, not an FRep object
  }
  const double* range = dimension->GetComponentRange(0);
  const int d = static_cast<int>(std::lround(range[0]));
  // An empty object (an upstream error, dimension 0) stays connectable to be fixed in place.
  return d == 0 || (d >= this->MinimumDimension && d <= this->MaximumDimension) ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkSMFRepObjectDomain::IsInDomain(vtkSMProperty* property)
{
  if (this->IsOptional)
  {
    return IN_DOMAIN;
  }
  auto* pp = vtkSMProxyProperty::SafeDownCast(property);
  if (!pp)
  {
    return NOT_IN_DOMAIN;
  }
  auto* ip = vtkSMInputProperty::SafeDownCast(property);
  const unsigned int count = pp->GetNumberOfUncheckedProxies();
  for (unsigned int i = 0; i < count; ++i)
  {
    auto* source = vtkSMSourceProxy::SafeDownCast(pp->GetUncheckedProxy(i));
    if (!source)
    {
      return NOT_IN_DOMAIN;
    }
    const unsigned int port = ip ? ip->GetUncheckedOutputPortForConnection(i) : 0;
    if (!this->IsInDomain(source->GetDataInformation(port)))
    {
      return NOT_IN_DOMAIN;
    }
  }
  return IN_DOMAIN;
}

//------------------------------------------------------------------------------
void vtkSMFRepObjectDomain::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumDimension: " << this->MinimumDimension << "\n";
  os << indent << "MaximumDimension: " << this->MaximumDimension << "\n";
}
