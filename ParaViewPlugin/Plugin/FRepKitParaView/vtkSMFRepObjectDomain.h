/**
 * @class   vtkSMFRepObjectDomain
 * @brief   input domain: the input is a vtkFRepObject (of a given dimension)
 *
 * ParaView 5.11's DataTypeDomain cannot name a plug-in data type ("not a known data object
 * type"), and a vtkFRepObject travels as the generic VTK_DATA_OBJECT. This domain recognises
 * it by what ParaView's data information does carry: the data set type VTK_DATA_OBJECT and the
 * field data array "FRepDimension" that every vtkFRepObject writes. Optionally the dimension
 * (number of free coordinates) must lie in [minimum_dimension, maximum_dimension]:
 *
 * \code{.xml}
 * <InputProperty name="Input" command="SetInputConnection">
 *   <FRepObjectDomain name="input_type" minimum_dimension="2" maximum_dimension="3"/>
 * </InputProperty>
 * \endcode
 *
 * An input whose data information is still empty (never updated) is accepted, as ParaView's
 * own domains do; so is an empty vtkFRepObject (an upstream parse error), whose dimension is 0
 * but which should still be fixable in place. The plug-in must be loaded on the client for
 * this class to exist there (REQUIRED_ON_CLIENT).
 *
 * @sa vtkSMDomain vtkSMDataTypeDomain vtkFRepObject
 */

#ifndef vtkSMFRepObjectDomain_h
#define vtkSMFRepObjectDomain_h

#include "FRepKitParaViewModule.h" // for export macro
#include "vtkSMDomain.h"

class vtkPVDataInformation;
class vtkSMSourceProxy;

class FREPKITPARAVIEW_EXPORT vtkSMFRepObjectDomain : public vtkSMDomain
{
public:
  static vtkSMFRepObjectDomain* New();
  vtkTypeMacro(vtkSMFRepObjectDomain, vtkSMDomain);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * IN_DOMAIN when every (unchecked) input of the input property is a vtkFRepObject whose
   * dimension is in range; NOT_IN_DOMAIN otherwise.
   */
  int IsInDomain(vtkSMProperty* property) override;

  /**
   * The test for one output port's data information (1 = accepted).
   */
  int IsInDomain(vtkPVDataInformation* information) const;

  ///@{
  /**
   * The accepted dimensions (XML minimum_dimension / maximum_dimension; default 0 and
   * VTK_INT_MAX: any).
   */
  vtkGetMacro(MinimumDimension, int);
  vtkGetMacro(MaximumDimension, int);
  ///@}

protected:
  vtkSMFRepObjectDomain();
  ~vtkSMFRepObjectDomain() override;

  int ReadXMLAttributes(vtkSMProperty* prop, vtkPVXMLElement* element) override;

  int MinimumDimension = 0;
  int MaximumDimension = VTK_INT_MAX;

private:
  vtkSMFRepObjectDomain(const vtkSMFRepObjectDomain&) = delete;
  void operator=(const vtkSMFRepObjectDomain&) = delete;
};

#endif
