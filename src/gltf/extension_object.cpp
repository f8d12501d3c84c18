#include "gltf/extension_object.h"

#include <cmath>

#include "core/input_error.h"

namespace vlit {
namespace {

const tinygltf::Value& empty_object() {
  static const tinygltf::Value kEmpty{tinygltf::Value::Object()};
  return kEmpty;
}

}  // namespace

ExtensionObject::ExtensionObject(const tinygltf::Value& value, std::string file, std::string path)
    : value_(&value), file_(std::move(file)), path_(std::move(path)) {
  if (!value.IsObject()) throw InputError(file_, "expected a JSON object", path_);
}

void ExtensionObject::fail(const std::string& key, const std::string& problem) const {
  throw InputError(file_, problem, key.empty() ? path_ : key_path(key));
}

bool ExtensionObject::has(const std::string& key) {
  read_.insert(key);
  return value_->Has(key);
}

double ExtensionObject::number(const std::string& key, std::optional<double> fallback) {
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "missing required number");
  }
  const tinygltf::Value& v = value_->Get(key);
  if (!v.IsNumber()) fail(key, "expected a number");
  const double x = v.GetNumberAsDouble();
  if (!std::isfinite(x)) fail(key, "number is not finite");
  return x;
}

Vec3d ExtensionObject::vec3(const std::string& key, std::optional<Vec3d> fallback) {
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "missing required [x, y, z]");
  }
  const tinygltf::Value& v = value_->Get(key);
  if (!v.IsArray() || v.ArrayLen() != 3) fail(key, "expected an array of 3 numbers");
  double c[3];
  for (int i = 0; i < 3; ++i) {
    const tinygltf::Value& e = v.Get(i);
    if (!e.IsNumber()) fail(key, "expected an array of 3 numbers");
    c[i] = e.GetNumberAsDouble();
    if (!std::isfinite(c[i])) fail(key, "number is not finite");
  }
  return {c[0], c[1], c[2]};
}

std::string ExtensionObject::string(const std::string& key, std::optional<std::string> fallback) {
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "missing required string");
  }
  const tinygltf::Value& v = value_->Get(key);
  if (!v.IsString()) fail(key, "expected a string");
  return v.Get<std::string>();
}

int ExtensionObject::index(const std::string& key) {
  if (!has(key)) fail(key, "missing required index");
  const tinygltf::Value& v = value_->Get(key);
  // tinygltf keeps integral JSON numbers as ints; a real like 1.0 is accepted if integral.
  if (!v.IsNumber()) fail(key, "expected an integer index");
  const double x = v.GetNumberAsDouble();
  if (!(x >= 0 && x <= 2147483647.0 && x == std::floor(x))) fail(key, "expected an integer index >= 0");
  return static_cast<int>(x);
}

ExtensionObject ExtensionObject::object(const std::string& key) {
  if (!has(key)) return ExtensionObject(empty_object(), file_, key_path(key));
  return ExtensionObject(value_->Get(key), file_, key_path(key));
}

std::vector<ExtensionObject> ExtensionObject::objects(const std::string& key) {
  if (!has(key)) fail(key, "missing required array");
  const tinygltf::Value& v = value_->Get(key);
  if (!v.IsArray()) fail(key, "expected an array");
  std::vector<ExtensionObject> out;
  for (std::size_t i = 0; i < v.ArrayLen(); ++i)
    out.emplace_back(v.Get(static_cast<int>(i)), file_, key_path(key) + "[" + std::to_string(i) + "]");
  return out;
}

std::vector<std::string> ExtensionObject::unread_keys() const {
  std::vector<std::string> out;
  for (const std::string& k : value_->Keys())
    if (!read_.count(k) && k != "name" && k != "extensions" && k != "extras") out.push_back(k);
  return out;
}

}  // namespace vlit
