#pragma once
// An owned object of a class hierarchy with value semantics: copying it copies the object through
// its virtual clone(), so a copied scene never shares a material or light with the original (the
// idea of C++26's std::polymorphic, P3019). `Base` declares
// `virtual std::unique_ptr<Base> clone() const`.
#include <concepts>
#include <memory>
#include <utility>

namespace lightpath {

template <typename Base>
class PolymorphicValue {
public:
    template <typename Derived>
        requires std::derived_from<Derived, Base>
    PolymorphicValue(Derived value) : object_(std::make_unique<Derived>(std::move(value))) {}
    PolymorphicValue(const PolymorphicValue& other) : object_(other.object_->clone()) {}
    PolymorphicValue& operator=(const PolymorphicValue& other) {
        if (this != &other) object_ = other.object_->clone();
        return *this;
    }
    PolymorphicValue(PolymorphicValue&&) noexcept = default;
    PolymorphicValue& operator=(PolymorphicValue&&) noexcept = default;

    Base& operator*() const { return *object_; }
    Base* operator->() const { return object_.get(); }

private:
    std::unique_ptr<Base> object_;
};

}  // namespace lightpath
