/**
 * @class   vtkFRepInformation
 * @brief   the n-D metadata of a vtkFRepObject as pipeline information keys
 *
 * Producers of vtkFRepObject (vtkFRepObjectAlgorithm subclasses) describe the object they will
 * produce in their RequestInformation, on the output port's information, with these keys; the
 * consumers (vtkFRepSlice, vtkFRepBoolean, vtkFRepSampler, vtkMultimediaMapper, ParaView's
 * slice) read them in their own RequestInformation instead of executing their input. Coordinates
 * are the MODEL's coordinates, 0-based, as in vtkFRepObject:
 *
 * - DIMENSION (integer): the number of free coordinates k;
 * - MODEL_DIMENSION (integer): the model's number of coordinates n;
 * - OBJECT_NAME (string): the model's object name (vtkFRepObject::GetObjectName());
 * - COORDINATE_NAMES (string vector, n): the name of every model coordinate;
 * - COORDINATE_RANGES (double vector, 2n): the interval [lo, hi] of every model coordinate;
 * - FIXED_VALUES (double vector, n): the value of every fixed coordinate, NaN where free;
 * - FREE_COORDINATES (integer vector, k): the model coordinate of each axis, in axis order;
 * - PARAMETERS (double vector): the a[] values a[1..] (absent when there are none).
 *
 * No key (no DIMENSION) means that no object will be produced: the output will be empty, and the
 * producer has reported why. The keys copy themselves from the first input to every output in
 * REQUEST_INFORMATION (CopyDefaultInformation), so a generic pass-through filter between two FRep
 * algorithms keeps them; vtkFRepObjectAlgorithm removes them from its outputs before its own
 * RequestInformation, so that a stale description never survives a failed pass.
 *
 * The data object itself (a vtkFRepObject without a producer, e.g. SetInputData) has no keys:
 * CompleteInputInformation() describes it from the object when its producer is a
 * vtkTrivialProducer, where the data is all there is. The field-data mirror of the object
 * (FRepDimension, FRepCoordinateNames, ...; see vtkFRepObject), which ParaView's panels read, is
 * unchanged: the keys are for the pipeline, the field data for the user interface.
 *
 * @sa vtkFRepObject vtkFRepObjectAlgorithm
 */
#ifndef vtkFRepInformation_h
#define vtkFRepInformation_h

#include "FRepKitSourcesModule.h" // for export macro
#include "vtkObject.h"

#include <array>  // for std::array
#include <string> // for std::string
#include <vector> // for std::vector

class vtkFRepObject;
class vtkInformation;
class vtkInformationDoubleVectorKey;
class vtkInformationIntegerKey;
class vtkInformationIntegerVectorKey;
class vtkInformationStringKey;
class vtkInformationStringVectorKey;

class FREPKITSOURCES_EXPORT vtkFRepInformation : public vtkObject
{
public:
  static vtkFRepInformation* New();
  vtkTypeMacro(vtkFRepInformation, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The keys (see the class description).
   */
  static vtkInformationIntegerKey* DIMENSION();
  static vtkInformationIntegerKey* MODEL_DIMENSION();
  static vtkInformationStringKey* OBJECT_NAME();
  static vtkInformationStringVectorKey* COORDINATE_NAMES();
  static vtkInformationDoubleVectorKey* COORDINATE_RANGES();
  static vtkInformationDoubleVectorKey* FIXED_VALUES();
  static vtkInformationIntegerVectorKey* FREE_COORDINATES();
  static vtkInformationDoubleVectorKey* PARAMETERS();
  ///@}

  /**
   * True when `info` describes an object (it has DIMENSION).
   */
  static bool Has(vtkInformation* info);

  /**
   * Removes every key of this class from `info`.
   */
  static void Remove(vtkInformation* info);

  /**
   * Sets the keys on `info` from a data object (removes them when `object` is null or has no
   * model).
   */
  static void SetFromObject(vtkInformation* info, vtkFRepObject* object);

  /**
   * Input information `inInfo` without keys whose producer is a vtkTrivialProducer (the input
   * was given as data, SetInputData) gets them from that data object. Returns Has(inInfo).
   */
  static bool CompleteInputInformation(vtkInformation* inInfo);

  /**
   * Asks the producer of `inInfo` for the whole object: piece 0 of 1, no ghost levels. Every
   * rank builds the full (indivisible) object, and the request is always the same, so that no
   * upstream algorithm re-executes because of pieces.
   */
  static void RequestWholeObject(vtkInformation* inInfo);

#ifndef __VTK_WRAP__
  /**
   * The metadata in one C++ value (model coordinates, 0-based), for algorithms that transform
   * it. Not wrapped: Python reads the keys.
   */
  struct Metadata
  {
    std::string ObjectName;
    std::vector<std::string> Names;            ///< per model coordinate
    std::vector<std::array<double, 2>> Ranges; ///< per model coordinate
    std::vector<double> FixedValues;           ///< per model coordinate, NaN where free
    std::vector<int> FreeCoordinates;          ///< model coordinate of each axis
    std::vector<double> Parameters;            ///< a[1..]

    int GetDimension() const { return static_cast<int>(this->FreeCoordinates.size()); }
    int GetModelDimension() const { return static_cast<int>(this->Names.size()); }
    bool IsCoordinateFixed(int coordinate) const;
    /** "" for a coordinate out of range. */
    std::string GetCoordinateName(int coordinate) const;
  };

  ///@{
  /**
   * Reads the keys (false, and `metadata` cleared, when `info` describes no object or the keys
   * are inconsistent), writes them, or describes a data object (false without a model).
   */
  static bool Get(vtkInformation* info, Metadata& metadata);
  static void Set(vtkInformation* info, const Metadata& metadata);
  static bool Describe(vtkFRepObject* object, Metadata& metadata);
  ///@}
#endif

protected:
  vtkFRepInformation() = default;
  ~vtkFRepInformation() override = default;

private:
  vtkFRepInformation(const vtkFRepInformation&) = delete;
  void operator=(const vtkFRepInformation&) = delete;
};

#endif
