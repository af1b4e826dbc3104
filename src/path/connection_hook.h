#pragma once
// A way for a caller to weigh every connection of a traced BDPT path in its own way, with the
// path builder knowing nothing of why (relt's tempered levels re-evaluate the BSDFs where the
// subpaths join: replica/tempered_targets.h).
#include "material/bsdf.h"
#include "path/vertex.h"

namespace relt {

// One strategy's connection as a hook sees it: the surface vertices it joins (null at a light or
// camera end), and its contribution and MIS weight with other BSDFs at those two vertices.
class ConnectionEnds {
 public:
  virtual const PathVertex* lightEnd() const = 0;
  virtual const PathVertex* cameraEnd() const = 0;
  // Null: the vertex's own BSDF.
  virtual Color value(const Bsdf* atLight, const Bsdf* atCamera) const = 0;
  virtual float misWeight(const Bsdf* atLight, const Bsdf* atCamera) const = 0;

 protected:
  ~ConnectionEnds() = default;
};

// With a hook set, strategies joined at a smooth (delta) vertex are connected too: the path's own
// contribution is zero there, but a hook may give it a value, and the one visibility ray serves
// both.
class ConnectionHook {
 public:
  virtual ~ConnectionHook() = default;
  // A new path is traced.
  virtual void beginPath() = 0;
  // Before the connection's visibility ray: true when the hook has a non-zero value for it, so the
  // ray is traced even where the path's own contribution is zero.
  virtual bool prepare(const ConnectionEnds& c) = 0;
  // After the ray, when it is not blocked: `own` is the luminance of the path's own MIS-weighted
  // contribution through this connection.
  virtual void add(const ConnectionEnds& c, double own) = 0;
};

}  // namespace relt
