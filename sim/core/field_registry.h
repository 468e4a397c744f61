// Structure-of-arrays particle storage with a registry of named fields.
//
// Every per-particle array lives here with a name, a unit and whether it belongs in checkpoints.
// Sorting, output, checkpoints and the restart-equals-continuous test all iterate the registry,
// so a field added by a new effect cannot be forgotten by any of them (docs/developer-guide.md code
// rule 5).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

#include "sim/core/error.h"
#include "sim/core/types.h"

namespace sim {

enum class ScalarKind { kReal, kInt32 };

// How a field's element type maps to flat storage: `components` scalars of `kind` each.
template <class T>
struct FieldTraits;
template <>
struct FieldTraits<Real> {
  static constexpr ScalarKind kind = ScalarKind::kReal;
  static constexpr int components = 1;
};
template <>
struct FieldTraits<Vec3> {
  static constexpr ScalarKind kind = ScalarKind::kReal;
  static constexpr int components = 3;
};
template <>
struct FieldTraits<Mat3> {
  static constexpr ScalarKind kind = ScalarKind::kReal;
  static constexpr int components = 9;
};
template <>
struct FieldTraits<std::int32_t> {
  static constexpr ScalarKind kind = ScalarKind::kInt32;
  static constexpr int components = 1;
};

struct FieldInfo {
  std::string name;   // e.g. "velocity"
  std::string unit;   // SI unit, e.g. "m/s"; "1" for dimensionless
  bool checkpointed;  // part of the state a resumed run needs to continue bit-identically
  bool written;       // written to output frames
};

class FieldBase {
 public:
  explicit FieldBase(FieldInfo info) : info_(std::move(info)) {}
  virtual ~FieldBase() = default;
  const FieldInfo& info() const { return info_; }
  virtual ScalarKind kind() const = 0;
  virtual int components() const = 0;
  virtual std::size_t size() const = 0;
  virtual void resize(std::size_t n) = 0;
  // Flat scalar storage: size() * components() scalars of kind().
  virtual const void* rawData() const = 0;
  virtual void* rawData() = 0;
  virtual const std::type_info& elementType() const = 0;

 private:
  FieldInfo info_;
};

// The most scalars of one field element (a Mat3).
inline constexpr std::size_t kMaxFieldComponents = 9;

template <class T>
class Field final : public FieldBase {
  static_assert(FieldTraits<T>::components <= kMaxFieldComponents);

 public:
  using FieldBase::FieldBase;
  ScalarKind kind() const override { return FieldTraits<T>::kind; }
  int components() const override { return FieldTraits<T>::components; }
  std::size_t size() const override { return values.size(); }
  void resize(std::size_t n) override { values.resize(n, T(zero())); }
  const void* rawData() const override { return values.data(); }
  void* rawData() override { return values.data(); }
  const std::type_info& elementType() const override { return typeid(T); }

  std::vector<T> values;

 private:
  static T zero() {
    if constexpr (std::is_arithmetic_v<T>) {
      return T(0);
    } else {
      return T::Zero();
    }
  }
};

// Reorders `components`-scalar elements in place so that element k becomes old element
// newToOld[k] (a permutation of 0..n-1), following its cycles: no copy of the field, one bit per
// element (`moved`).
template <class S>
void permuteScalars(S* data, std::size_t components, const std::vector<Index>& newToOld,
                    std::vector<bool>& moved) {
  const std::size_t n = newToOld.size(), c = components;
  moved.assign(n, false);
  S held[kMaxFieldComponents];
  for (std::size_t start = 0; start < n; ++start) {
    if (moved[start]) continue;
    moved[start] = true;
    std::size_t src = newToOld[start];
    if (src == start) continue;
    std::copy(data + start * c, data + start * c + c, held);
    std::size_t dst = start;
    while (src != start) {
      std::copy(data + src * c, data + src * c + c, data + dst * c);
      moved[src] = true;
      dst = src;
      src = newToOld[dst];
    }
    std::copy(held, held + c, data + dst * c);
  }
}

// Keeps elements keep[0..m) (increasing), in that order, at the front.
template <class S>
void selectScalars(S* data, std::size_t components, const std::vector<Index>& keep) {
  const std::size_t c = components;
  for (std::size_t k = 0; k < keep.size(); ++k)
    std::copy(data + keep[k] * c, data + keep[k] * c + c, data + k * c);
}

// A set of equally long named fields. References returned by add()/get() stay valid for the
// registry's lifetime (each field is heap-allocated once).
class FieldRegistry {
 public:
  template <class T>
  std::vector<T>& add(FieldInfo info) {
    if (has(info.name)) throw SimError("field '" + info.name + "' registered twice");
    auto field = std::make_unique<Field<T>>(std::move(info));
    field->resize(size_);
    auto& values = field->values;
    fields_.push_back(std::move(field));
    return values;
  }

  // Adds the field unless it exists already (with the same type): effects that share a field
  // (e.g. two solvers needing "pressure") call this.
  template <class T>
  std::vector<T>& addOrGet(FieldInfo info) {
    if (has(info.name)) return get<T>(info.name);
    return add<T>(std::move(info));
  }

  template <class T>
  std::vector<T>& get(std::string_view name) {
    return typed<T>(name).values;
  }
  template <class T>
  const std::vector<T>& get(std::string_view name) const {
    return const_cast<FieldRegistry*>(this)->typed<T>(name).values;
  }

  bool has(std::string_view name) const { return find(name) != nullptr; }
  const FieldBase* find(std::string_view name) const {
    for (const auto& f : fields_)
      if (f->info().name == name) return f.get();
    return nullptr;
  }
  FieldBase* find(std::string_view name) {
    return const_cast<FieldBase*>(std::as_const(*this).find(name));
  }

  std::size_t size() const { return size_; }
  void resize(std::size_t n) {
    size_ = n;
    for (auto& f : fields_) f->resize(n);
  }
  // Reorders every field so that new element k is old element newToOld[k] (a permutation of all
  // elements), in place: a scratch copy of the fields would add about a tenth to a particle's
  // memory (docs/benchmarks.md, "Memory"). Serial; it runs every WorldParameters::zSortInterval
  // steps, and the Z-order re-sort moves elements only locally. No allocation after the first call
  // at a given size.
  void permute(const std::vector<Index>& newToOld) {
    require(newToOld.size() == size_, "FieldRegistry::permute: one index per element needed");
    for (auto& f : fields_)
      withScalars(*f,
                  [&](auto* data, std::size_t c) { permuteScalars(data, c, newToOld, moved_); });
  }
  // Keeps only the elements keep[0..m) (strictly increasing indices), in that order.
  void select(const std::vector<Index>& keep) {
    for (std::size_t k = 0; k < keep.size(); ++k)
      require(keep[k] < size_ && (k == 0 || keep[k] > keep[k - 1]),
              "FieldRegistry::select: indices must be increasing and in range");
    for (auto& f : fields_)
      withScalars(*f, [&](auto* data, std::size_t c) { selectScalars(data, c, keep); });
    resize(keep.size());
  }

  // Iteration over all fields in registration order (deterministic).
  auto begin() const { return fields_.begin(); }
  auto end() const { return fields_.end(); }
  std::size_t fieldCount() const { return fields_.size(); }
  // Bytes held by all fields (for `tamponade plan` memory estimates and pipeline tests).
  std::size_t bytes() const {
    std::size_t total = 0;
    for (const auto& f : fields_)
      total += f->size() * static_cast<std::size_t>(f->components()) *
               (f->kind() == ScalarKind::kReal ? sizeof(Real) : sizeof(std::int32_t));
    return total;
  }

 private:
  template <class T>
  Field<T>& typed(std::string_view name) {
    FieldBase* base = find(name);
    if (!base) throw SimError("no particle field named '" + std::string(name) + "'");
    auto* field = dynamic_cast<Field<T>*>(base);
    if (!field) throw SimError("particle field '" + std::string(name) + "' has another type");
    return *field;
  }

  // op(data, components) with the field's flat storage as its scalar type.
  template <class Op>
  static void withScalars(FieldBase& f, Op&& op) {
    const auto c = static_cast<std::size_t>(f.components());
    if (f.kind() == ScalarKind::kReal)
      op(static_cast<Real*>(f.rawData()), c);
    else
      op(static_cast<std::int32_t*>(f.rawData()), c);
  }

  std::size_t size_ = 0;
  std::vector<std::unique_ptr<FieldBase>> fields_;
  std::vector<bool> moved_;  // permute()'s marks
};

}  // namespace sim
