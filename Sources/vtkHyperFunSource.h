/**
 * @class   vtkHyperFunSource
 * @brief   HyperFun text or .hf file -> vtkFRepObject (source and reader)
 *
 * vtkHyperFunSource parses a HyperFun program, compiles one of its objects and produces a
 * vtkFRepObject with every coordinate free. The program comes from FileName when it is set (the
 * source then doubles as the .hf reader), else from ModelText.
 *
 * The object evaluated is ObjectName, compared case-insensitively; when ObjectName is empty,
 * the object called my_model, else the first object of the program (as the original
 * interpreter does). An ObjectName the program does not define is an error that lists the
 * objects.
 *
 * Parameters are the a[] values a[1..] (missing ones are 0). Coordinate ranges set the interval
 * of each coordinate of the output (SetCoordinateRange, 0-based). Coordinates without one get the
 * solid's own bounds (UseSolidBounds, on by default; frep::mesh::find_coordinate_bounds: the n-D
 * solid's bounds when it is bounded, else x1..x3 cover the sections at the centre and corners of
 * x4..'s intervals, with 5% margin), so that a unit ball is sampled over about [-1.1, 1.1], not
 * hfp's [-10, 10]. Where the solid cannot be bounded (a half-space; enclosures too loose), or
 * with UseSolidBounds off, they get DefaultCoordinateRange, [-10, 10] like hfp's default box, and
 * a warning says why (once per model: not again when only a[] or the ranges change).
 *
 * Errors: every diagnostic of the parser and the compiler is reported through its own
 * vtkErrorMacro as "file:line:col: error: message" ("<string>" is the file name of ModelText),
 * and the output is left empty (an initialised vtkFRepObject without a model). Nothing crashes.
 *
 PIPELINE: the program is read, parsed and compiled in RequestInformation, which publishes the
 * object's metadata (dimension, coordinate names and intervals, a[]) as vtkFRepInformation keys,
 * so that downstream filters plan their outputs without executing this source; diagnostics are
 * reported there, once. The compiled model is cached until the source is modified (its MTime):
 * RequestData reuses it without reading or parsing again, and after a change the program is
 * read again but parsed again only when its text (or ObjectName) differs, so changing
 * Parameters or ranges re-specialises the model without parsing. A file edited on disk is read
 * again after Modified() (ParaView's Reload Files does that).
 *
 * Every rank of a parallel run builds the full object (CAN_HANDLE_PIECE_REQUEST is set, see
 * vtkFRepObjectAlgorithm): the object cannot be split or sent between ranks.
 *
 * @sa vtkFRepObject vtkFRepObjectAlgorithm vtkFRepInformation vtkFRepImplicitFunction
 */
#ifndef vtkHyperFunSource_h
#define vtkHyperFunSource_h

#include "FRepKitSourcesModule.h" // for export macro
#include "vtkFRepObjectAlgorithm.h"
#include "vtkTimeStamp.h" // for vtkTimeStamp

#include <array>  // for std::array
#include <memory> // for std::shared_ptr
#include <string> // for std::string
#include <vector> // for std::vector

namespace frep
{
class Model;
struct LoadOptions;
struct Tape;
namespace ast
{
struct Program;
}
}

class vtkFRepObject;

class FREPKITSOURCES_EXPORT vtkHyperFunSource : public vtkFRepObjectAlgorithm
{
public:
  static vtkHyperFunSource* New();
  vtkTypeMacro(vtkHyperFunSource, vtkFRepObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The HyperFun program text (default none). Used when FileName is not set.
   */
  vtkSetStringMacro(ModelText);
  vtkGetStringMacro(ModelText);
  ///@}

  ///@{
  /**
   * A model file to read (default none): HyperFun (.hf), or a tape of the field's benchmark
   * format (.vm: one object my_model, F = -value). When set, it wins over ModelText.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The object to compile, case-insensitive (default none: my_model, else the first object).
   */
  vtkSetStringMacro(ObjectName);
  vtkGetStringMacro(ObjectName);
  ///@}

  ///@{
  /**
   * The a[] parameters: SetParameter(i, v) sets a[i + 1] (0-based i; the list grows with zeros
   * as needed); SetNumberOfParameters(n) truncates or pads with zeros (default 0 parameters).
   * GetParameter(i) is 0 beyond the values given.
   */
  void SetParameter(int i, double value);
  double GetParameter(int i) const;
  void SetNumberOfParameters(int n);
  int GetNumberOfParameters() const { return static_cast<int>(this->Parameters.size()); }
  void RemoveAllParameters() { this->SetNumberOfParameters(0); }
  ///@}

  ///@{
  /**
   * Interval [lo, hi] of coordinate i (0-based: x[i + 1]) in the output. Coordinates without
   * an interval of their own get the solid's bounds (UseSolidBounds) or DefaultCoordinateRange.
   * lo > hi is an error. GetCoordinateRange gives the interval coordinate i gets: after the
   * source has updated its information (UpdateInformation), the solid's bounds where they were
   * used; before, the interval set or DefaultCoordinateRange.
   */
  void SetCoordinateRange(int i, double lo, double hi);
  void GetCoordinateRange(int i, double range[2]) const;
  void RemoveAllCoordinateRanges();
  ///@}

  ///@{
  /**
   * Interval of every coordinate without one of its own (default [-10, 10], hfp's box).
   */
  vtkSetVector2Macro(DefaultCoordinateRange, double);
  vtkGetVector2Macro(DefaultCoordinateRange, double);
  ///@}

  ///@{
  /**
   * Give coordinates without an interval of their own the solid's bounds (default on; see the
   * class description). Off: DefaultCoordinateRange, as hfp and FRepKit before 0.2 did.
   */
  vtkSetMacro(UseSolidBounds, vtkTypeBool);
  vtkGetMacro(UseSolidBounds, vtkTypeBool);
  vtkBooleanMacro(UseSolidBounds, vtkTypeBool);
  ///@}

  ///@{
  /**
   * User functions the program may call (Documentation/user-functions.md). AddUserLibrary: a
   * HyperFun file (.hf) whose objects the model calls like its own earlier objects, or a shared
   * library implementing frepkit_user.h (loaded when the model is built; a failure is an error
   * naming the library; call Modified() after a library file changes). AddShape: the object (e.g. the output of
   * vtkPolyDataToFRep, or any k-D vtkFRepObject) as the function `name(x)` over its free
   * coordinates, with its enclosures and gradients; the object is used as it is when added
   * (call AddShape again after it changes).
   */
  void AddUserLibrary(const char* path);
  void RemoveAllUserLibraries();
  int GetNumberOfUserLibraries() const { return static_cast<int>(this->UserLibraries.size()); }
  void AddShape(const char* name, vtkFRepObject* object);
  void RemoveAllShapes();
  int GetNumberOfShapes() const { return static_cast<int>(this->ShapeNames.size()); }
  ///@}

protected:
  /**
   * Defaults: no ModelText, FileName or ObjectName, no parameters, UseSolidBounds on,
   * DefaultCoordinateRange [-10, 10]; no input port, one output port (vtkFRepObject).
   */
  vtkHyperFunSource();
  ~vtkHyperFunSource() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * The compiled model, brought up to date (see PIPELINE in the class description): null when
   * the program cannot be read, parsed or compiled (reported once per change).
   */
  std::shared_ptr<const frep::Model> UpdateModel();

  /**
   * The parsed program of the last UpdateModel() (null when it did not parse), e.g. to list its
   * objects.
   */
  std::shared_ptr<const frep::ast::Program> GetProgram() const { return this->CachedProgram; }

  char* ModelText = nullptr;
  char* FileName = nullptr;
  char* ObjectName = nullptr;
  double DefaultCoordinateRange[2] = { -10.0, 10.0 };
  vtkTypeBool UseSolidBounds = 1;
  std::vector<double> Parameters;
  // Per coordinate: has an interval of its own, and the interval.
  std::vector<bool> HasCoordinateRange;
  std::vector<std::array<double, 2>> CoordinateRanges;
  std::vector<std::string> UserLibraries;
  std::vector<std::string> ShapeNames;
  std::vector<std::shared_ptr<const frep::Tape>> ShapeTapes;

  /**
   * The program's text and the name its diagnostics give (FileName's contents, or ModelText as
   * "<string>"); false after reporting why there is none. Subclasses that write their program
   * (vtkFRepMetamorphosis) override it.
   */
  virtual bool ReadProgramText(std::string& text, std::string& sourceName);

  /**
   * Puts the user libraries (AddUserLibrary) and shapes (AddShape) into `options`; false after
   * reporting a shape that cannot be registered.
   */
  virtual bool AddUserFunctions(frep::LoadOptions& options);

private:
  vtkHyperFunSource(const vtkHyperFunSource&) = delete;
  void operator=(const vtkHyperFunSource&) = delete;

  // Reads, parses and compiles (or reuses the cached model); reports every diagnostic.
  std::shared_ptr<const frep::Model> BuildModel();
  // The interval of every coordinate of `model` (UseSolidBounds), into FoundRanges; warns once
  // when the solid cannot be bounded.
  void UpdateRanges(const frep::Model& model);
  // Fills `output` with the model, the coordinate intervals and a[].
  void FillObject(const std::shared_ptr<const frep::Model>& model, vtkFRepObject* output) const;

  // The cached model and program, what they were built from, and when (UpdateModel).
  vtkTimeStamp ModelTime;
  std::shared_ptr<const frep::ast::Program> CachedProgram;
  std::shared_ptr<const frep::Model> CachedModel;
  std::string CachedText;
  std::string CachedSourceName;
  std::string CachedObjectName;
  vtkTimeStamp UserFunctionTime; // AddShape/AddUserLibrary: the cache is stale
  vtkTimeStamp CachedTime;
  // The intervals UpdateRanges chose for the current model (empty: none yet).
  std::vector<std::array<double, 2>> FoundRanges;
  // The model the unbounded-solid warning was given for: once per model, not per parameter.
  std::weak_ptr<const frep::Model> WarnedModel;
};

#endif
