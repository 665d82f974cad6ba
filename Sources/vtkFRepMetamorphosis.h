/**
 * @class   vtkFRepMetamorphosis
 * @brief   key shapes on a lattice of parameters -> one vtkFRepObject of higher dimension
 *
 * vtkFRepMetamorphosis blends key objects (HyperFun files, AddKey) placed on a lattice of
 * parameters (AddLatticeAxis: nodes per parameter; none: one parameter over all keys) into one
 * object whose last coordinates are the parameters, each over [0, 1]: the engine's
 * metamorphosis (FRep/Morph/morph_text.h, Documentation/metamorphosis.md), written as HyperFun
 * with the keys' objects pasted in and then loaded exactly as vtkHyperFunSource loads a program
 * (it is one: ObjectName, Parameters, coordinate ranges, UseSolidBounds, AddUserLibrary and
 * AddShape work as there; the libraries and shapes are the keys' own). FileName and ModelText
 * are ignored. Linear weights on a 2 x 2 lattice are the paper's bilinear formula, bit for bit.
 * The parameters' coordinates get the interval [0, 1] unless SetCoordinateRange gives them
 * another (the keys' coordinates get the solid's bounds, as in vtkHyperFunSource).
 *
 * Errors (a key file that does not load, keys of different sizes, a lattice that does not match
 * the keys, clashing object names) are reported through vtkErrorMacro as file:line:col, and the
 * output is left empty.
 *
 * @sa vtkHyperFunSource vtkFRepSlice
 */
#ifndef vtkFRepMetamorphosis_h
#define vtkFRepMetamorphosis_h

#include "FRepKitSourcesModule.h" // for export macro
#include "vtkHyperFunSource.h"

#include <memory> // for std::shared_ptr
#include <string> // for std::string
#include <utility> // for std::pair
#include <vector>  // for std::vector

namespace frep
{
class UserFunctionRegistry;
}

class FREPKITSOURCES_EXPORT vtkFRepMetamorphosis : public vtkHyperFunSource
{
public:
  static vtkFRepMetamorphosis* New();
  vtkTypeMacro(vtkFRepMetamorphosis, vtkHyperFunSource);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The keys in lattice order, the first parameter fastest (on 2 x 2: (0, 0), (1, 0), (0, 1),
   * (1, 1)): a HyperFun file and its object (null or empty: the file's my_model, else its first
   * object). Default none.
   */
  void AddKey(const char* file, const char* object = nullptr);
  void RemoveAllKeys();
  int GetNumberOfKeys() const { return static_cast<int>(this->KeyFiles.size()); }
  ///@}

  ///@{
  /**
   * Nodes per parameter, one call per axis (each 2 to 64). Default none: one axis of all keys.
   */
  void AddLatticeAxis(int nodes);
  void RemoveAllLatticeAxes();
  int GetNumberOfLatticeAxes() const { return static_cast<int>(this->Lattice.size()); }
  ///@}

  enum
  {
    LINEAR = 0,      ///< hat functions (the paper's bilinear on 2 x 2)
    CATMULL_ROM = 1, ///< through every key, C1
    B_SPLINE = 2     ///< clamped uniform B-spline: C2, reaches the end keys only
  };
  ///@{
  /**
   * The weights along each parameter (default LINEAR).
   */
  vtkSetClampMacro(Scheme, int, LINEAR, B_SPLINE);
  vtkGetMacro(Scheme, int);
  void SetSchemeToLinear() { this->SetScheme(LINEAR); }
  void SetSchemeToCatmullRom() { this->SetScheme(CATMULL_ROM); }
  void SetSchemeToBSpline() { this->SetScheme(B_SPLINE); }
  ///@}

  enum
  {
    ALIGN_NONE = 0,     ///< every key in place (the paper)
    ALIGN_CENTROID = 1, ///< each key travels with the blended centroid
    ALIGN_SIZE = 2      ///< and is scaled to the blended size (its F alike)
  };
  ///@{
  /**
   * How the keys are aligned as the blend proceeds (default ALIGN_NONE; see
   * Documentation/metamorphosis.md, "Keys aligned as the blend proceeds").
   */
  vtkSetClampMacro(Alignment, int, ALIGN_NONE, ALIGN_SIZE);
  vtkGetMacro(Alignment, int);
  ///@}

  enum
  {
    NORMALISE_NONE = 0,    ///< the keys' values as they are (the paper)
    NORMALISE_DISTANCE = 1 ///< each key's sampled signed distance added beyond a band
  };
  ///@{
  /**
   * How the keys' values are made comparable (default NORMALISE_NONE; see
   * Documentation/metamorphosis.md, "Comparable fields"). The keys' zero sets stay exact.
   */
  vtkSetClampMacro(Normalisation, int, NORMALISE_NONE, NORMALISE_DISTANCE);
  vtkGetMacro(Normalisation, int);
  ///@}

  enum
  {
    TIMING_LINEAR = 0,   ///< the blend moves at a constant rate (the paper)
    TIMING_EASE = 1,     ///< starts and stops gently at every key (smoothstep)
    TIMING_EASE_IN = 2,  ///< leaves each key slowly
    TIMING_EASE_OUT = 3, ///< arrives at each key slowly
    TIMING_HOLD = 4      ///< each key alone for HoldFraction/2 of the way on either side
  };
  ///@{
  /**
   * How the blend moves between neighbouring keys on every parameter (default TIMING_LINEAR;
   * Documentation/metamorphosis.md, "Timing and key weights"). Every key stays itself at its node.
   */
  vtkSetClampMacro(Timing, int, TIMING_LINEAR, TIMING_HOLD);
  vtkGetMacro(Timing, int);
  ///@}

  ///@{
  /**
   * TIMING_HOLD's fraction of each segment during which a key is held (default 0.5, in
   * [0, 0.99]).
   */
  vtkSetClampMacro(HoldFraction, double, 0.0, 0.99);
  vtkGetMacro(HoldFraction, double);
  ///@}

  ///@{
  /**
   * A key's own weight: `key` is its object name, `expression` a number (global) or a HyperFun
   * expression of the point x[] (local; mx[] is the point in the keys' space, for a field
   * function: vol(mx)). Weights are at least 0.001 and normalised; keys not named weigh 1. Needs
   * LINEAR or B_SPLINE (an error with CATMULL_ROM).
   */
  void AddKeyWeight(const char* key, const char* expression);
  void RemoveAllKeyWeights();
  int GetNumberOfKeyWeights() const { return static_cast<int>(this->KeyWeights.size()); }
  ///@}

protected:
  /**
   * Defaults: no keys, no lattice axes, LINEAR, ALIGN_NONE, NORMALISE_NONE, TIMING_LINEAR with
   * HoldFraction 0.5, no key weights.
   */
  vtkFRepMetamorphosis();
  ~vtkFRepMetamorphosis() override;

  /// The metamorphosis written as HyperFun (the keys pasted), named "<metamorphosis>".
  bool ReadProgramText(std::string& text, std::string& sourceName) override;
  /// The base's functions and the keys' distances of the last program written.
  bool AddUserFunctions(frep::LoadOptions& options) override;

  std::vector<std::string> KeyFiles;
  std::vector<std::string> KeyObjects;
  std::vector<int> Lattice;
  int Scheme = LINEAR;
  int Alignment = ALIGN_NONE;
  int Normalisation = NORMALISE_NONE;
  int Timing = TIMING_LINEAR;
  double HoldFraction = 0.5;
  std::vector<std::pair<std::string, std::string>> KeyWeights;
  std::shared_ptr<const frep::UserFunctionRegistry> Distances; ///< of the last program written

private:
  vtkFRepMetamorphosis(const vtkFRepMetamorphosis&) = delete;
  void operator=(const vtkFRepMetamorphosis&) = delete;
};

#endif
