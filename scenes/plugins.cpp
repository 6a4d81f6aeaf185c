#include "scenes/plugins.h"

#include <map>
#include <set>
#include <vector>

namespace tr {

namespace {

struct Entry {
  const char* tag;
  const char* type;
  PluginSupport support;
  const char* reason;
};

const char* const POLARIZATION = "out of scope: polarization (twinray renders unpolarized RGB)";
const char* const MEDIA = "out of scope: participating media (twinray renders surfaces in vacuum)";
const char* const CURVES = "out of scope: curve primitives";
const char* const NOT_YET = "not implemented by twinray";

// Every plugin of Mitsuba 3.8's src/<kind>/ folders, by the XML tag that instantiates it.
const Entry TABLE[] = {
    // shapes
    {"shape", "obj", PluginSupport::Supported, ""},
    {"shape", "ply", PluginSupport::Supported, ""},
    {"shape", "serialized", PluginSupport::Supported, ""},
    {"shape", "rectangle", PluginSupport::Supported, ""},
    {"shape", "cube", PluginSupport::Supported, ""},
    {"shape", "sphere", PluginSupport::Supported, ""},
    {"shape", "disk", PluginSupport::Supported, ""},
    {"shape", "cylinder", PluginSupport::Supported, ""},
    {"shape", "shapegroup", PluginSupport::Supported, ""},
    {"shape", "instance", PluginSupport::Supported, ""},
    {"shape", "bsplinecurve", PluginSupport::OutOfScope, CURVES},
    {"shape", "linearcurve", PluginSupport::OutOfScope, CURVES},
    {"shape", "sdfgrid", PluginSupport::OutOfScope, "out of scope: signed distance field grids"},
    {"shape", "ellipsoids", PluginSupport::OutOfScope, "out of scope: ellipsoid splat primitives"},
    {"shape", "ellipsoidsmesh", PluginSupport::OutOfScope,
     "out of scope: ellipsoid splat primitives"},
    {"shape", "blender", PluginSupport::Unimplemented, NOT_YET},
    {"shape", "merge", PluginSupport::Unimplemented, NOT_YET},
    // BSDFs
    {"bsdf", "diffuse", PluginSupport::Supported, ""},
    {"bsdf", "conductor", PluginSupport::Supported, ""},
    {"bsdf", "roughconductor", PluginSupport::Supported, ""},
    {"bsdf", "dielectric", PluginSupport::Supported, ""},
    {"bsdf", "roughdielectric", PluginSupport::Supported, ""},
    {"bsdf", "thindielectric", PluginSupport::Supported, ""},
    {"bsdf", "plastic", PluginSupport::Supported, ""},
    {"bsdf", "roughplastic", PluginSupport::Supported, ""},
    {"bsdf", "principled", PluginSupport::Supported, ""},
    {"bsdf", "twosided", PluginSupport::Supported, ""},
    {"bsdf", "mask", PluginSupport::Supported, ""},
    // twinray extension: alpha testing as real-time renderers do it (core/alpha_test.h)
    {"bsdf", "alphatest", PluginSupport::Supported, ""},
    {"bsdf", "normalmap", PluginSupport::Supported, ""},
    {"bsdf", "bumpmap", PluginSupport::Supported, ""},
    {"bsdf", "blendbsdf", PluginSupport::Supported, ""},
    {"bsdf", "pplastic", PluginSupport::Supported, ""},
    {"bsdf", "polarizer", PluginSupport::OutOfScope, POLARIZATION},
    {"bsdf", "retarder", PluginSupport::OutOfScope, POLARIZATION},
    {"bsdf", "circular", PluginSupport::OutOfScope, POLARIZATION},
    {"bsdf", "measured_polarized", PluginSupport::OutOfScope, POLARIZATION},
    {"bsdf", "hair", PluginSupport::OutOfScope, "out of scope: hair fibres"},
    {"bsdf", "measured", PluginSupport::Unimplemented, NOT_YET},
    {"bsdf", "null", PluginSupport::Unimplemented, NOT_YET},
    {"bsdf", "principledthin", PluginSupport::Unimplemented, NOT_YET},
    // textures
    {"texture", "bitmap", PluginSupport::Supported, ""},
    {"texture", "checkerboard", PluginSupport::Supported, ""},
    {"texture", "mesh_attribute", PluginSupport::Supported, ""},
    {"texture", "volume", PluginSupport::OutOfScope, MEDIA},
    // emitters
    {"emitter", "area", PluginSupport::Supported, ""},
    {"emitter", "point", PluginSupport::Supported, ""},
    {"emitter", "directional", PluginSupport::Supported, ""},
    {"emitter", "constant", PluginSupport::Supported, ""},
    {"emitter", "envmap", PluginSupport::Supported, ""},
    {"emitter", "spot", PluginSupport::Supported, ""},
    {"emitter", "projector", PluginSupport::Supported, ""},
    {"emitter", "directionalarea", PluginSupport::Unimplemented, NOT_YET},
    {"emitter", "sunsky", PluginSupport::Unimplemented, NOT_YET},
    {"emitter", "timed_sunsky", PluginSupport::Unimplemented, NOT_YET},
    // sensors, films, filters, samplers
    {"sensor", "perspective", PluginSupport::Supported, ""},
    {"sensor", "thinlens", PluginSupport::Supported, ""},
    {"sensor", "orthographic", PluginSupport::Supported, ""},
    {"sensor", "batch", PluginSupport::Unimplemented, NOT_YET},
    {"sensor", "distant", PluginSupport::Unimplemented, NOT_YET},
    {"sensor", "irradiancemeter", PluginSupport::Unimplemented, NOT_YET},
    {"sensor", "radiancemeter", PluginSupport::Unimplemented, NOT_YET},
    {"film", "hdrfilm", PluginSupport::Supported, ""},
    {"film", "specfilm", PluginSupport::OutOfScope,
     "out of scope: spectral films (twinray renders RGB)"},
    {"rfilter", "box", PluginSupport::Supported, ""},
    {"rfilter", "tent", PluginSupport::Supported, ""},
    {"rfilter", "gaussian", PluginSupport::Supported, ""},
    {"rfilter", "mitchell", PluginSupport::Supported, ""},
    {"rfilter", "catmullrom", PluginSupport::Supported, ""},
    {"rfilter", "lanczos", PluginSupport::Supported, ""},
    {"sampler", "independent", PluginSupport::Supported, ""},
    {"sampler", "stratified", PluginSupport::Supported, ""},
    {"sampler", "multijitter", PluginSupport::Supported, ""},
    {"sampler", "orthogonal", PluginSupport::Supported, ""},
    {"sampler", "ldsampler", PluginSupport::Supported, ""},
    // twinray samplers beyond Mitsuba (pbrt-v4's)
    {"sampler", "sobol", PluginSupport::Supported, ""},
    {"sampler", "zsobol", PluginSupport::Supported, ""},
    // integrators
    {"integrator", "path", PluginSupport::Supported, ""},
    {"integrator", "direct", PluginSupport::Supported, ""},
    {"integrator", "moment", PluginSupport::Supported, ""},
    {"integrator", "aov", PluginSupport::Supported, ""},
    // twinray integrators beyond Mitsuba (pbrt-v4's)
    {"integrator", "ambientocclusion", PluginSupport::Supported, ""},
    {"integrator", "stokes", PluginSupport::OutOfScope, POLARIZATION},
    {"integrator", "volpath", PluginSupport::OutOfScope, MEDIA},
    {"integrator", "volpathmis", PluginSupport::OutOfScope, MEDIA},
    {"integrator", "prbvolpath", PluginSupport::OutOfScope, MEDIA},
    {"integrator", "ptracer", PluginSupport::Unimplemented, NOT_YET},
    {"integrator", "depth", PluginSupport::Unimplemented, NOT_YET},
};

// Tags whose every plugin is out of scope.
const std::map<std::string, const char*> OUT_OF_SCOPE_TAGS = {
    {"medium", MEDIA}, {"phase", MEDIA}, {"volume", MEDIA}};

void visit(const Node& node, std::set<const Node*>& seen) {
  if (!seen.insert(&node).second) return;
  if (node.tag != "scene") {
    PluginStatus s = plugin_status(node.tag, node.type);
    if (s.support != PluginSupport::Supported) {
      std::string message = to_string(node.loc) + ": " + describe(node) +
                            ": not supported by twinray: " + node.type + " (" + s.reason + ")";
      throw UnsupportedPluginError(message, node.tag, node.type, s.support);
    }
  }
  for (const Property& p : node.props)
    if (p.kind == PropertyKind::Object) visit(*p.object, seen);
}

}  // namespace

PluginStatus plugin_status(const std::string& tag, const std::string& type) {
  auto whole_tag = OUT_OF_SCOPE_TAGS.find(tag);
  if (whole_tag != OUT_OF_SCOPE_TAGS.end()) return {PluginSupport::OutOfScope, whole_tag->second};
  for (const Entry& e : TABLE)
    if (tag == e.tag && type == e.type) return {e.support, e.reason};
  return {PluginSupport::Unknown, "Mitsuba 3 has no such plugin"};
}

void check_plugins(const Node& root) {
  std::set<const Node*> seen;
  visit(root, seen);
}

}  // namespace tr
