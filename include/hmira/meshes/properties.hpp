// hmira/meshes/properties.hpp
// Per-element user data (normals, colours, UVs, ...) for hmira's own meshes. Every property
// array grows with its element kind, is reset to its default when a mesh reuses a deleted
// element's slot, and is permuted by garbage collection together with the connectivity, so a
// property never goes out of step with the elements it describes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <typeindex>
#include <utility>
#include <vector>

#include "handles.hpp"

namespace hmira {

namespace detail {

class property_array_base {
public:
    explicit property_array_base(std::string name) : name_(std::move(name)) {}
    virtual ~property_array_base() = default;
    virtual void resize(std::size_t n) = 0;
    virtual void push_back() = 0;
    /// Sets element i back to the default value (a reused slot starts as a new element).
    virtual void reset(std::size_t i) = 0;
    /// Keeps element i at new index old_to_new[i]; entries equal to UINT32_MAX are dropped.
    virtual void compact(std::span<const std::uint32_t> old_to_new, std::size_t new_size) = 0;
    virtual std::unique_ptr<property_array_base> clone() const = 0;
    virtual std::type_index type() const = 0;
    const std::string& name() const noexcept { return name_; }

private:
    std::string name_;
};

template <class T>
class property_array final : public property_array_base {
public:
    property_array(std::string name, T default_value)
        : property_array_base(std::move(name)), default_(std::move(default_value)) {}

    void resize(std::size_t n) override { data.resize(n, default_); }
    void push_back() override { data.push_back(default_); }
    void reset(std::size_t i) override { data[i] = default_; }
    void compact(std::span<const std::uint32_t> old_to_new, std::size_t new_size) override {
        std::vector<T> out(new_size, default_);
        for (std::size_t i = 0; i < old_to_new.size() && i < data.size(); ++i)
            if (old_to_new[i] != UINT32_MAX) out[old_to_new[i]] = std::move(data[i]);
        data = std::move(out);
    }
    std::unique_ptr<property_array_base> clone() const override { return std::make_unique<property_array>(*this); }
    std::type_index type() const override { return typeid(T); }

    std::vector<T> data;

private:
    T default_;
};

}  // namespace detail

/// A reference to one property array, indexed by the element's handle: `normals[v] = n;`.
/// It stays valid while the property exists on the mesh that created it (through additions
/// and garbage collection); a copy of the mesh has its own arrays, fetched again by name.
template <class Handle, class T>
class property {
public:
    /// An invalid property, or one referring to `array` (made by the meshes).
    ///@{
    property() = default;
    explicit property(detail::property_array<T>* array) : array_(array) {}
    ///@}

    /// The value of element h.
    ///@{
    decltype(auto) operator[](Handle h) { return array_->data[h.index]; }
    decltype(auto) operator[](Handle h) const { return std::as_const(array_->data)[h.index]; }
    ///@}
    /// Whether this refers to a property array.
    bool valid() const noexcept { return array_ != nullptr; }
    /// The property's name.
    const std::string& name() const { return array_->name(); }
    /// All values, indexed by element index (deleted elements included until garbage collection).
    ///@{
    std::vector<T>& values() { return array_->data; }
    const std::vector<T>& values() const { return array_->data; }
    ///@}

private:
    detail::property_array<T>* array_ = nullptr;
};

/// The set of property arrays of one element kind. Used by the meshes, not by users directly.
template <class Handle>
class property_registry {
public:
    /// Empty; copies clone every array (a copied mesh owns its properties); moves keep them.
    ///@{
    property_registry() = default;
    property_registry(const property_registry& other) : size_(other.size_) {
        for (const auto& a : other.arrays_) arrays_.push_back(a->clone());
    }
    property_registry& operator=(const property_registry& other) {
        if (this != &other) {
            property_registry copy(other);
            *this = std::move(copy);
        }
        return *this;
    }
    property_registry(property_registry&&) noexcept = default;
    property_registry& operator=(property_registry&&) noexcept = default;
    ///@}

    /// Adds a property, or returns the existing one of the same name and type. Returns an
    /// invalid property if the name exists with another type.
    template <class T>
    property<Handle, T> add(std::string_view name, T default_value = T{}) {
        if (auto existing = find<T>(name)) return *existing;
        for (const auto& a : arrays_)
            if (a->name() == name) return {};
        auto array = std::make_unique<detail::property_array<T>>(std::string(name), std::move(default_value));
        array->resize(size_);
        auto* raw = array.get();
        arrays_.push_back(std::move(array));
        return property<Handle, T>(raw);
    }

    /// The property of that name and type, if there is one.
    template <class T>
    std::optional<property<Handle, T>> find(std::string_view name) const {
        for (const auto& a : arrays_)
            if (a->name() == name && a->type() == typeid(T))
                return property<Handle, T>(static_cast<detail::property_array<T>*>(a.get()));
        return std::nullopt;
    }

    /// Removes a property by name; returns whether one was removed.
    bool remove(std::string_view name) {
        for (auto it = arrays_.begin(); it != arrays_.end(); ++it)
            if ((*it)->name() == name) {
                arrays_.erase(it);
                return true;
            }
        return false;
    }

    /// Names of all properties, in creation order.
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto& a : arrays_) out.push_back(a->name());
        return out;
    }

    /// Element bookkeeping done by the meshes: one more element, element i reused (its values
    /// back to the defaults), n elements, and compaction keeping element i at old_to_new[i]
    /// (UINT32_MAX: dropped).
    ///@{
    void push_back() {
        ++size_;
        for (auto& a : arrays_) a->push_back();
    }
    void reset(std::size_t i) {
        for (auto& a : arrays_) a->reset(i);
    }
    void resize(std::size_t n) {
        size_ = n;
        for (auto& a : arrays_) a->resize(n);
    }
    void compact(std::span<const std::uint32_t> old_to_new, std::size_t new_size) {
        size_ = new_size;
        for (auto& a : arrays_) a->compact(old_to_new, new_size);
    }
    ///@}
    /// Number of elements each array holds.
    std::size_t size() const noexcept { return size_; }

private:
    std::vector<std::unique_ptr<detail::property_array_base>> arrays_;
    std::size_t size_ = 0;
};

/// The per-vertex property functions of hmira's meshes (each mesh derives from the
/// with_*_properties of its element kinds). Add returns the existing property of that name
/// and type, or an invalid one if the name has another type; get finds one; remove drops one
/// and says whether it existed. Properties follow garbage collection.
class with_vertex_properties {
public:
    /// Adds (or gets) a vertex property, find one, remove one by name.
    ///@{
    template <class T>
    property<vertex_handle, T> add_vertex_property(std::string_view name, T init = T{}) {
        return vertex_props_.template add<T>(name, std::move(init));
    }
    template <class T>
    std::optional<property<vertex_handle, T>> get_vertex_property(std::string_view name) const {
        return vertex_props_.template find<T>(name);
    }
    bool remove_vertex_property(std::string_view name) { return vertex_props_.remove(name); }
    ///@}

protected:
    property_registry<vertex_handle> vertex_props_;  ///< grown, compacted and cleared by the mesh
};

/// The per-face property functions (see with_vertex_properties).
class with_face_properties {
public:
    /// Adds (or gets) a face property, find one, remove one by name.
    ///@{
    template <class T>
    property<face_handle, T> add_face_property(std::string_view name, T init = T{}) {
        return face_props_.template add<T>(name, std::move(init));
    }
    template <class T>
    std::optional<property<face_handle, T>> get_face_property(std::string_view name) const {
        return face_props_.template find<T>(name);
    }
    bool remove_face_property(std::string_view name) { return face_props_.remove(name); }
    ///@}

protected:
    property_registry<face_handle> face_props_;  ///< grown, compacted and cleared by the mesh
};

/// The per-edge property functions (see with_vertex_properties).
class with_edge_properties {
public:
    /// Adds (or gets) an edge property, find one, remove one by name.
    ///@{
    template <class T>
    property<edge_handle, T> add_edge_property(std::string_view name, T init = T{}) {
        return edge_props_.template add<T>(name, std::move(init));
    }
    template <class T>
    std::optional<property<edge_handle, T>> get_edge_property(std::string_view name) const {
        return edge_props_.template find<T>(name);
    }
    bool remove_edge_property(std::string_view name) { return edge_props_.remove(name); }
    ///@}

protected:
    property_registry<edge_handle> edge_props_;  ///< grown, compacted and cleared by the mesh
};

/// The per-halfedge property functions (see with_vertex_properties).
class with_halfedge_properties {
public:
    /// Adds (or gets) a halfedge property, find one, remove one by name.
    ///@{
    template <class T>
    property<halfedge_handle, T> add_halfedge_property(std::string_view name, T init = T{}) {
        return halfedge_props_.template add<T>(name, std::move(init));
    }
    template <class T>
    std::optional<property<halfedge_handle, T>> get_halfedge_property(std::string_view name) const {
        return halfedge_props_.template find<T>(name);
    }
    bool remove_halfedge_property(std::string_view name) { return halfedge_props_.remove(name); }
    ///@}

protected:
    property_registry<halfedge_handle> halfedge_props_;  ///< grown, compacted and cleared by the mesh
};

}  // namespace hmira
