/**
 * @class   vtkFRepObject
 * @brief   an n-D FRep object travelling down a VTK pipeline
 *
 * vtkFRepObject holds a compiled HyperFun object (a frep::Model: immutable, shared between
 * copies and threads) together with what the pipeline has decided about it so far:
 *
 * - the model's coordinates x1..xn ("coordinates", 0-based indices 0..n-1 here), each with a
 *   name (default "x1".."xn") and an interval [lo, hi] (default [-10, 10]);
 * - which coordinates are fixed to a value (a slice) and which stay free, and the order of the
 *   free ones: free coordinate (axis) i of the object is model coordinate
 *   GetFreeCoordinate(i). GetDimension() is the number of free coordinates;
 * - the a[] parameters.
 *
 * GetTape() returns the model specialised to these values (frep::Model::specialise: fixed
 * coordinates and a[] folded away), whose inputs are the free coordinates in axis order; it is
 * cached until the object changes and safe to call from several threads.
 * GetEvaluationDescription() bundles that tape with the names and intervals of its inputs.
 *
 * The data type id is the generic VTK_DATA_OBJECT (a new id breaks ParaView's data information,
 * see DESIGN.md). ShallowCopy shares the model (ParaView copies every output through
 * NewInstance + ShallowCopy); DeepCopy compiles a model of its own from the same (immutable)
 * program, or shares a composed model (frep::combine), which has no program. The metadata is mirrored into field data arrays, the only part ParaView's
 * information panel and domains can see:
 *   FRepDimension (int, 1 tuple: free coordinates), FRepModelDimension (int),
 *   FRepObjectName (string), FRepCoordinateNames (string, per free coordinate),
 *   FRepIntervals (double, 2 components, per free coordinate),
 *   FRepFixedValues (double, per model coordinate, NaN where free),
 *   FRepParameters (double, a[1..]).
 * These arrays are written by the object; edit the object, not the arrays.
 *
 * @sa vtkHyperFunSource vtkFRepImplicitFunction
 */
#ifndef vtkFRepObject_h
#define vtkFRepObject_h

#include "FRepKitSourcesModule.h" // for export macro
#include "vtkDataObject.h"

#include "Compiler/model.h" // for frep::Model, frep::Tape, frep::Specialisation

#include <array>  // for std::array
#include <memory> // for std::shared_ptr
#include <mutex>  // for std::mutex
#include <string> // for std::string
#include <vector> // for std::vector

class vtkInformation;
class vtkInformationVector;

class FREPKITSOURCES_EXPORT vtkFRepObject : public vtkDataObject
{
public:
  static vtkFRepObject* New();
  vtkTypeMacro(vtkFRepObject, vtkDataObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The generic id VTK_DATA_OBJECT: ParaView cannot handle a new one (see DESIGN.md).
   */
  int GetDataObjectType() override { return VTK_DATA_OBJECT; }

  /**
   * Removes the model and all metadata (an empty object, dimension 0).
   */
  void Initialize() override;

  ///@{
  /**
   * ShallowCopy shares the (immutable) model; DeepCopy compiles a new model from the same
   * program (a composed model, which has none, is shared). Both copy the coordinates, fixed values, parameters and field data. A source
   * that is not a vtkFRepObject only has its field data copied (as vtkDataObject does).
   */
  void ShallowCopy(vtkDataObject* src) override;
  void DeepCopy(vtkDataObject* src) override;
  ///@}

  /**
   * Memory in kibibytes: the field data and the metadata (the shared model is not counted).
   */
  unsigned long GetActualMemorySize() override;

  /**
   * Sets the model: every coordinate free in increasing order, names "x1".."xn", intervals
   * [-10, 10], no parameters. A null model is the same as Initialize().
   */
  void SetModel(std::shared_ptr<const frep::Model> model);
  std::shared_ptr<const frep::Model> GetModel() const { return this->Model; }
  bool HasModel() const { return this->Model != nullptr; }
  /** The model's object name (lower-case, as HyperFun stores it), or "" without a model. */
  std::string GetObjectName() const;

  /** Number of free coordinates: the dimension of the object (0 without a model). */
  int GetDimension() const { return static_cast<int>(this->FreeCoordinates.size()); }
  /** Number of coordinates of the model, x_dim (0 without a model). */
  int GetModelDimension() const { return static_cast<int>(this->Coordinates.size()); }

  /** Model coordinate (0-based) of free coordinate `axis`, or -1 if out of range. */
  int GetFreeCoordinate(int axis) const;
  /** The free coordinates in axis order. */
  const std::vector<int>& GetFreeCoordinates() const { return this->FreeCoordinates; }

  ///@{
  /**
   * Name of model coordinate `coordinate` (0-based; default "x<coordinate+1>"). Out of range:
   * an error, and "" from the getter.
   */
  void SetCoordinateName(int coordinate, const std::string& name);
  std::string GetCoordinateName(int coordinate) const;
  ///@}

  ///@{
  /**
   * Interval [lo, hi] of model coordinate `coordinate` (default [-10, 10]). lo > hi is an error.
   */
  void SetCoordinateRange(int coordinate, double lo, double hi);
  void GetCoordinateRange(int coordinate, double range[2]) const;
  ///@}

  ///@{
  /**
   * Fixes model coordinate `coordinate` to `value` (it leaves the free coordinates) or makes it
   * free again (appended as the last axis). Releasing a free coordinate does nothing.
   */
  void FixCoordinate(int coordinate, double value);
  void ReleaseCoordinate(int coordinate);
  bool IsCoordinateFixed(int coordinate) const;
  /** The fixed value, NaN when the coordinate is free or out of range. */
  double GetFixedValue(int coordinate) const;
  ///@}

  /**
   * Chooses the free coordinates and their order: `coordinates` lists model coordinates
   * (0-based, no repeats); every coordinate not listed must be fixed already. Returns false
   * (and reports an error, changing nothing) otherwise.
   */
  bool SetFreeCoordinates(const std::vector<int>& coordinates);

  ///@{
  /**
   * The a[] parameters a[1..] (missing values are 0 for the model, extra ones are ignored).
   */
  void SetParameters(const std::vector<double>& parameters);
  const std::vector<double>& GetParameters() const { return this->Parameters; }
  int GetNumberOfParameters() const { return static_cast<int>(this->Parameters.size()); }
  /** a[i + 1], 0 when i is beyond the values given. */
  double GetParameter(int i) const;
  ///@}

  /**
   * What the evaluators need: the fixed values, a[] and the order of the free coordinates.
   */
  frep::Specialisation GetSpecialisation() const;

  /**
   * The model specialised with the fixed values and parameters; its inputs are the free
   * coordinates in axis order, its outputs F and s[1..]. Cached until the object changes;
   * thread-safe. Null without a model.
   */
  std::shared_ptr<const frep::Tape> GetTape() const;

  /** An evaluator-friendly description of the object, see GetEvaluationDescription(). */
  struct EvaluationDescription
  {
    std::shared_ptr<const frep::Tape> Tape;    ///< inputs = free coordinates in axis order
    std::vector<int> Coordinates;              ///< model coordinate of each tape input
    std::vector<std::string> Names;            ///< name of each tape input
    std::vector<std::array<double, 2>> Ranges; ///< interval of each tape input
    int AttributeCount = 0;                    ///< s[] outputs after F (s_dim)
  };
  /** The tape, with the names and intervals of its inputs (empty without a model). */
  EvaluationDescription GetEvaluationDescription() const;

  ///@{
  /**
   * Retrieves an instance of this class from an information object.
   */
  static vtkFRepObject* GetData(vtkInformation* info);
  static vtkFRepObject* GetData(vtkInformationVector* v, int i = 0);
  ///@}

protected:
  vtkFRepObject();
  ~vtkFRepObject() override;

private:
  vtkFRepObject(const vtkFRepObject&) = delete;
  void operator=(const vtkFRepObject&) = delete;

  struct Coordinate
  {
    std::string Name;
    double Range[2] = { -10.0, 10.0 };
    bool Fixed = false;
    double Value = 0.0;
  };

  bool CheckCoordinate(int coordinate, const char* method) const;
  void CopyState(vtkFRepObject* src);
  // Called after every change of the state: drops the cached tape, rewrites the field data,
  // calls Modified().
  void StateChanged();
  void UpdateFieldData();

  std::shared_ptr<const frep::Model> Model;
  std::vector<Coordinate> Coordinates;
  std::vector<int> FreeCoordinates;
  std::vector<double> Parameters;

  mutable std::mutex TapeMutex;
  mutable std::shared_ptr<const frep::Tape> CachedTape;
};

#endif
