// A metamorphosis written as a HyperFun model (issue 29): key objects of d coordinates placed on
// a lattice of k parameters (Morph/lattice_weights.h) become one object of d + k coordinates,
// x[d+1..d+k] the parameters, each over [0, 1]:
//
//   F(x, t) = sum over the lattice's nodes of  w(t) * F_key(x)
//
// evaluated axis by axis (the first parameter's keys blended first, then those blends along the
// second, ...), so that a linear 2 x 2 lattice is the paper's formula operation for operation:
// Meta5D = (Cat*(1-x4) + Robot*x4)*(1-x5) + (NiHon*(1-x4) + Rob_let*x4)*x5, bit for bit.
//
// The result is HyperFun text, so it is an object everywhere an object is: load_model compiles
// it (the weights' if-chains become selects, folded away when the parameters are fixed: a
// spreadsheet cell's tape holds only the keys whose weights are not 0; a key whose weight is 0
// is not called, so it adds exactly 0), and the original interpreter reads the pasted form.
// Two forms:
//   Library  the text calls the keys' objects from their own files: load it with those files as
//            HyperFun libraries (MorphText::libraries; frepkit --library).
//   Pasted   the key files' objects are copied in, from each file's first object to its end:
//            one file, as the original interpreter needs (Examples/homotopic/meta5d.hf).
#pragma once

#include "Compiler/load_model.h"
#include "Language/diagnostic.h"
#include "Morph/key_distance.h"
#include "Morph/key_frame.h"
#include "Morph/lattice_weights.h"
#include "Morph/timing.h"

#include <string>
#include <vector>

namespace frep::morph
{

struct Key
{
  std::string file; ///< a HyperFun model file
  std::string
    object; ///< its object (any case); empty: the file's default (my_model, else the first)
};

/// A key's own weight (issue 29, item 3): how much the key counts against the others, globally
/// (a number) or point by point (an expression of the point). One HyperFun expression over the
/// morph's x[] (x[1..d] the point, x[d+1..] the parameters: a weight can change along the
/// blend), its a[], and mx[1..d], the point as an array of d items (for a field: vol(mx)).
/// Each key's lattice weight w is multiplied by max(expression, 0.001) and the products are
/// normalised to sum to 1, so at its node a key is still itself exactly.
struct KeyWeight
{
  std::string key;        ///< the key's object name (any case); every node it stands at
  std::string expression; ///< e.g. "2", "1 + max(x[3], 0)", "vol(mx)"
};

struct MorphSpec
{
  /// In lattice order, the first parameter axis fastest: key i_0 + n_0 (i_1 + n_1 (...)). The
  /// same key may stand at several nodes. Every key has the same x[] and a[] sizes and s[1].
  std::vector<Key> keys;
  /// Nodes per parameter axis (each >= 2); their product is the number of keys.
  std::vector<int> lattice;
  Interpolation scheme = Interpolation::Linear;
  /// How the parameter moves between neighbouring keys (timing.h), on every axis.
  Timing timing;
  /// Keys' own weights (KeyWeight); a key not named weighs 1. Not with Catmull-Rom, whose
  /// weights go negative (the normalised sum could vanish).
  std::vector<KeyWeight> key_weights;
  /// Keys aligned as the blend proceeds (key_frame.h): each key evaluated where it would be had
  /// its centroid (and size) travelled to the weights' blend of the keys' centroids (and sizes),
  /// measured on `frame_samples`^d points of each key. The corners stay the keys exactly.
  Alignment alignment = Alignment::None;
  int frame_samples = 48;
  /// Keys' values made comparable (key_distance.h): with Distance, beyond a band of two cells
  /// about its surface each key gains its signed distance sampled on `distance_samples`^3
  /// points, on its own side only (the key's sign, zero set and topology are kept exactly;
  /// values at the corners are the normalised key's, no longer the raw key's).
  Normalisation normalisation = Normalisation::None;
  int distance_samples = 96;
  /// The object written (a HyperFun name: a letter, then letters, digits, _). Unless it is
  /// my_model, a my_model equal to it follows, so it is the file's default object.
  std::string name = "morph";
};

enum class KeyPlacement
{
  Library,
  Pasted
};

/// A key's sampled distance, as the text calls it: `function`(x) over x[1..3].
struct DistanceVolume
{
  std::string function; ///< "mdist_" + the key's object name
  std::string key;      ///< the key's object name
  shapes::VolumeGrid grid;
};

struct MorphText
{
  std::string text; ///< empty when diagnostics say why
  /// Library placement: the key files, in first-use order, for LoadOptions::libraries.
  std::vector<std::string> libraries;
  int x_dim = 0; ///< of the object written: the keys' plus the lattice's axes
  /// Normalisation::Distance: the keys' distances the text calls, and the same as functions to
  /// load it with (LoadOptions::functions, merged with any others). A file written from `text`
  /// needs them again when loaded: frepkit morph writes each grid as a .vti beside it.
  std::vector<DistanceVolume> distances;
  std::shared_ptr<const UserFunctionRegistry> functions;
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return diagnostics.empty(); }
};

/// Writes the metamorphosis. The keys are read with `key_options` (their functions and
/// libraries; its object is ignored). Never throws for bad input: a key that does not load, keys
/// of different sizes, a lattice that does not match the keys, clashing object names or a bad
/// name come back as diagnostics (file:line:col where there is a place).
MorphText write_morph(const MorphSpec& spec,
  KeyPlacement placement,
  const LoadOptions& key_options = {});

} // namespace frep::morph
