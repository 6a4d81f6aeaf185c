#include "scenes/gltf/gltf_accessors.h"

#include <algorithm>
#include <cstring>

#include "scenes/gltf/gltf_json.h"
#include "scenes/gltf/gltf_tangents.h"

namespace tr {

using namespace gltf_json;

namespace {

// Spec "Accessor Data Types": componentType.
const int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123,
          kUnsignedInt = 5125, kFloat = 5126;
// Spec mesh.primitive.mode.
const int kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6;
// The most values an accessor without a bufferView may hold (1 GiB as doubles).
const size_t kMaxValues = size_t(1) << 27;

size_t component_size(int type) {
  switch (type) {
    case kByte:
    case kUnsignedByte:
      return 1;
    case kShort:
    case kUnsignedShort:
      return 2;
    case kUnsignedInt:
    case kFloat:
      return 4;
    default:
      return 0;
  }
}

template <typename T>
T load(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);  // glTF is little-endian, as the hosts twinray builds for
  return v;
}

// Spec "Animation" (normalized integers): the decoding of each component type.
double component(const char* p, int type, bool normalized) {
  switch (type) {
    case kByte: {
      double c = load<int8_t>(p);
      return normalized ? std::max(c / 127.0, -1.0) : c;
    }
    case kUnsignedByte:
      return normalized ? load<uint8_t>(p) / 255.0 : load<uint8_t>(p);
    case kShort: {
      double c = load<int16_t>(p);
      return normalized ? std::max(c / 32767.0, -1.0) : c;
    }
    case kUnsignedShort:
      return normalized ? load<uint16_t>(p) / 65535.0 : load<uint16_t>(p);
    case kUnsignedInt:
      return load<uint32_t>(p);
    default:
      return load<float>(p);
  }
}

int type_components(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  return 0;  // matrices: no mesh attribute twinray reads is one
}

}  // namespace

GltfAccessors::Layout GltfAccessors::layout(size_t a) {
  std::string p = "/accessors/" + std::to_string(a);
  const json& o = object(list(doc_, "accessors")[a], p);
  Layout l;
  l.component_type = int(integer(o, "componentType", -1, p));
  if (!component_size(l.component_type))
    throw GltfFieldError(p + "/componentType",
                         "unknown component type " + std::to_string(l.component_type));
  const json* type = member(o, "type");
  if (!type || !type->is_string()) throw GltfFieldError(p, "\"type\" (a string) is required");
  l.components = type_components(type->get<std::string>());
  if (const json* n = member(o, "normalized")) {
    if (!n->is_boolean()) throw GltfFieldError(p + "/normalized", "expected true or false");
    l.normalized = n->get<bool>();
    if (l.normalized && (l.component_type == kFloat || l.component_type == kUnsignedInt))
      throw GltfFieldError(p + "/normalized", "only byte and short components can be normalized");
  }
  l.count = size_t(integer(o, "count", -1, p));
  if (l.count == 0) throw GltfFieldError(p + "/count", "must be at least 1");
  return l;
}

std::vector<double> GltfAccessors::decode(size_t a, const Layout& l) {
  std::string p = "/accessors/" + std::to_string(a);
  const json& o = list(doc_, "accessors")[a];
  const size_t element = component_size(l.component_type) * size_t(l.components);
  // Elements [0, count) of `element` bytes at `offset` + i `stride` must lie in `bytes`: checked
  // before anything is allocated for them.
  auto check_fit = [&](std::string_view bytes, size_t offset, size_t stride, size_t count,
                       const std::string& where) {
    if (offset > bytes.size() || bytes.size() - offset < element ||
        count - 1 > (bytes.size() - offset - element) / stride)
      throw GltfFieldError(where, std::to_string(count) + " elements of " +
                                      std::to_string(element) + " bytes from byte " +
                                      std::to_string(offset) + " do not fit the buffer view (" +
                                      std::to_string(bytes.size()) + " bytes)");
  };
  auto read = [&](std::string_view bytes, size_t offset, size_t stride, size_t count, auto&& put) {
    for (size_t i = 0; i < count; ++i)
      for (int c = 0; c < l.components; ++c)
        put(i, c,
            component(
                bytes.data() + offset + i * stride + size_t(c) * component_size(l.component_type),
                l.component_type, l.normalized));
  };
  std::string_view bytes;
  size_t offset = 0, stride = 0;
  if (const json* v = member(o, "bufferView")) {
    bytes = buffers_.view(index(*v, p + "/bufferView", list(doc_, "bufferViews").size()), &stride);
    offset = size_t(integer(o, "byteOffset", 0, p));
    stride = stride ? stride : element;
    check_fit(bytes, offset, stride, l.count, p);
  } else if (member(o, "byteOffset")) {
    throw GltfFieldError(p + "/byteOffset", "given without a bufferView");
  } else if (l.count > kMaxValues / size_t(l.components)) {
    // Without a bufferView the file's size does not bound the count.
    throw GltfFieldError(p + "/count", "more elements than twinray reads without a bufferView (" +
                                           std::to_string(kMaxValues) + " values)");
  }
  std::vector<double> out(l.count * size_t(l.components), 0.0);  // spec: no bufferView, zeros
  if (member(o, "bufferView"))
    read(bytes, offset, stride, l.count,
         [&](size_t i, int c, double x) { out[i * size_t(l.components) + size_t(c)] = x; });
  if (const json* s = member(o, "sparse")) {
    // Spec "Sparse Accessors": `count` elements replaced, at strictly increasing indices.
    std::string sp = p + "/sparse";
    object(*s, sp);
    size_t count = size_t(integer(*s, "count", -1, sp));
    if (count == 0 || count > l.count)
      throw GltfFieldError(sp + "/count", "must lie in [1, the accessor's count]");
    const json* si = member(*s, "indices");
    const json* sv = member(*s, "values");
    if (!si || !sv) throw GltfFieldError(sp, "\"indices\" and \"values\" are required");
    std::string ip = sp + "/indices", vp = sp + "/values";
    object(*si, ip), object(*sv, vp);
    int index_type = int(integer(*si, "componentType", -1, ip));
    if (index_type != kUnsignedByte && index_type != kUnsignedShort && index_type != kUnsignedInt)
      throw GltfFieldError(ip + "/componentType", "must be an unsigned byte, short or int");
    std::string_view ib = buffers_.view(reference(doc_, *si, "bufferView", "bufferViews", ip));
    size_t ioff = size_t(integer(*si, "byteOffset", 0, ip)), isize = component_size(index_type);
    if (ioff > ib.size() || (ib.size() - ioff) / isize < count)
      throw GltfFieldError(ip, "the indices do not fit their buffer view");
    std::vector<size_t> at(count);
    for (size_t i = 0; i < count; ++i) {
      at[i] = size_t(component(ib.data() + ioff + i * isize, index_type, false));
      if (at[i] >= l.count || (i > 0 && at[i] <= at[i - 1]))
        throw GltfFieldError(ip,
                             "indices must increase strictly and stay below the accessor's count");
    }
    std::string_view vb = buffers_.view(reference(doc_, *sv, "bufferView", "bufferViews", vp));
    size_t voff = size_t(integer(*sv, "byteOffset", 0, vp));
    check_fit(vb, voff, element, count, vp);
    read(vb, voff, element, count,
         [&](size_t i, int c, double x) { out[at[i] * size_t(l.components) + size_t(c)] = x; });
  } else if (!member(o, "bufferView")) {
    throw GltfFieldError(p, "neither \"bufferView\" nor \"sparse\": no data");
  }
  return out;
}

std::vector<float> GltfAccessors::floats(size_t a, int components) {
  Layout l = layout(a);
  if (l.components != components)
    throw GltfFieldError(
        "/accessors/" + std::to_string(a) + "/type",
        "expected " + std::string(components == 1 ? "SCALAR" : "VEC" + std::to_string(components)) +
            " for this use");
  std::vector<double> v = decode(a, l);
  return std::vector<float>(v.begin(), v.end());
}

std::vector<std::uint32_t> GltfAccessors::indices(size_t a) {
  Layout l = layout(a);
  std::string p = "/accessors/" + std::to_string(a);
  if (l.components != 1 || l.normalized ||
      (l.component_type != kUnsignedByte && l.component_type != kUnsignedShort &&
       l.component_type != kUnsignedInt))
    throw GltfFieldError(
        p, "vertex indices must be SCALAR unsigned byte, short or int, not normalized");
  std::vector<double> v = decode(a, l);
  return std::vector<std::uint32_t>(v.begin(), v.end());
}

ImportedMesh GltfAccessors::primitive(size_t m, size_t k) {
  std::string p = "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(k);
  const json& prim = list(doc_, "meshes")[m]["primitives"][k];
  const json* attributes = member(prim, "attributes");
  if (!attributes || !attributes->is_object() || !attributes->contains("POSITION"))
    throw GltfFieldError(p, "\"attributes\" with POSITION is required");
  std::string ap = p + "/attributes";
  size_t accessors = list(doc_, "accessors").size();
  ImportedMesh mesh;
  mesh.positions = floats(index((*attributes)["POSITION"], ap + "/POSITION", accessors), 3);
  const size_t vertices = mesh.positions.size() / 3;
  auto attribute = [&](const char* name, int components, std::vector<float>& into) {
    const json* a = member(*attributes, name);
    if (!a) return;
    into = floats(index(*a, ap + "/" + name, accessors), components);
    if (into.size() != vertices * size_t(components))
      throw GltfFieldError(ap + "/" + name, "has another count of elements than POSITION");
  };
  attribute("NORMAL", 3, mesh.normals);
  attribute("TEXCOORD_0", 2, mesh.uv);
  std::vector<float> tangent;
  attribute("TANGENT", 4, tangent);
  if (!tangent.empty() && !mesh.normals.empty()) set_gltf_tangents(mesh, tangent);

  std::vector<std::uint32_t> v;
  if (const json* i = member(prim, "indices")) {
    v = indices(index(*i, p + "/indices", accessors));
    for (std::uint32_t x : v)
      if (x >= vertices)
        throw GltfFieldError(p + "/indices", "vertex index " + std::to_string(x) +
                                                 " out of range (" + std::to_string(vertices) +
                                                 " vertices)");
  } else {
    v.resize(vertices);
    for (size_t x = 0; x < vertices; ++x) v[x] = std::uint32_t(x);
  }
  // Spec "Meshes" (topology types): triangle i of a strip is (v_i, v_{i+1+i%2}, v_{i+2-i%2}),
  // of a fan (v_{i+1}, v_{i+2}, v_0).
  int mode = int(integer(prim, "mode", kTriangles, p));
  if (mode == kTriangles) {
    if (v.size() % 3 != 0)
      throw GltfFieldError(p, std::to_string(v.size()) + " vertices do not make whole triangles");
    mesh.triangles = std::move(v);
  } else if (mode == kTriangleStrip) {
    for (size_t i = 0; i + 2 < v.size(); ++i)
      mesh.triangles.insert(mesh.triangles.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
  } else if (mode == kTriangleFan) {
    for (size_t i = 0; i + 2 < v.size(); ++i)
      mesh.triangles.insert(mesh.triangles.end(), {v[i + 1], v[i + 2], v[0]});
  } else {
    throw GltfFieldError(p + "/mode", "not a triangle mode");
  }
  return mesh;
}

}  // namespace tr
