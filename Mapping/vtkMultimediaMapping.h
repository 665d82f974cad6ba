/**
 * @class   vtkMultimediaMapping
 * @brief   the multimedia mapping of an n-D FRep object: which coordinate drives what
 *
 * vtkMultimediaMapping holds a frep::mapping::Spec: for each geometric coordinate x_i of a
 * model, the multimedia coordinates it drives through the unit interval (world axes, time,
 * spreadsheet grid axes, colour, transparency, transformations, sound), and the settings of the
 * animation, spreadsheet, rendering and audio. It is read from and written to the JSON mapping
 * file of `frepkit map` (Documentation/mapping-file.md), or set from C++ with SetSpec().
 *
 * Errors in a file name their place, "FILE: coordinates.x4[1].range: lo must be < hi", each
 * through vtkErrorMacro; the previous specification is kept then. GetErrors() lists the last
 * load's errors.
 *
 * @sa vtkMultimediaMapper vtkSpreadsheetLayout
 */
#ifndef vtkMultimediaMapping_h
#define vtkMultimediaMapping_h

#include "FRepKitMappingModule.h" // for export macro
#include "vtkObject.h"

#include "Mapping/mapping_spec.h" // for frep::mapping::Spec

#include <string> // for std::string
#include <vector> // for std::vector

class FREPKITMAPPING_EXPORT vtkMultimediaMapping : public vtkObject
{
public:
  static vtkMultimediaMapping* New();
  vtkTypeMacro(vtkMultimediaMapping, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Reads a JSON mapping file. Returns false (and reports every error) if it cannot be read or
   * is invalid; the current specification is then unchanged.
   */
  bool LoadFile(const std::string& path);

  /**
   * Parses JSON text; `sourceName` prefixes the error messages (default "<string>").
   */
  bool LoadJSON(const std::string& text, const std::string& sourceName = "<string>");

  /**
   * The specification as JSON text (LoadJSON of it gives the same specification).
   */
  std::string ToJSON() const;

  /**
   * Writes ToJSON() to `path` (a temporary file renamed when complete). False on failure.
   */
  bool SaveFile(const std::string& path) const;

  ///@{
  /**
   * The specification. Default: a default-constructed frep::mapping::Spec (no coordinates
   * mapped, 10 s at 24 fps, 1280 x 720).
   */
  const frep::mapping::Spec& GetSpec() const { return this->Spec; }
  void SetSpec(const frep::mapping::Spec& spec);
  ///@}

  /**
   * The errors of the last LoadFile/LoadJSON ("place: message"), empty after a success.
   */
  const std::vector<std::string>& GetErrors() const { return this->Errors; }

protected:
  vtkMultimediaMapping();
  ~vtkMultimediaMapping() override;

private:
  vtkMultimediaMapping(const vtkMultimediaMapping&) = delete;
  void operator=(const vtkMultimediaMapping&) = delete;

  frep::mapping::Spec Spec;
  std::vector<std::string> Errors;
};

#endif
