#pragma once
// One registry per family of types. Each type's .cpp adds its Entry (which has `TypeSchema schema`
// and `int rank`) from a static registrar, so a new type is one file. Listings come out by rank
// then name, never in link order.
#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace lightpath {

template <class Entry>
class TypeRegistry {
public:
    // A function-local static: safe to call from other translation units' static initialisers.
    static TypeRegistry& instance() {
        static TypeRegistry registry;
        return registry;
    }

    void add(Entry entry) {
        if (find(entry.schema.name)) {
            throw std::logic_error(std::string(entry.schema.family) + " type \"" + std::string(entry.schema.name) +
                                   "\" is registered twice");
        }
        entries_.push_back(std::make_unique<Entry>(std::move(entry)));
    }

    const Entry* find(std::string_view name) const {
        for (const auto& e : entries_)
            if (e->schema.name == name) return e.get();
        return nullptr;
    }

    std::vector<const Entry*> entries() const {
        std::vector<const Entry*> sorted;
        for (const auto& e : entries_) sorted.push_back(e.get());
        std::sort(sorted.begin(), sorted.end(), [](const Entry* a, const Entry* b) {
            return a->rank != b->rank ? a->rank < b->rank : a->schema.name < b->schema.name;
        });
        return sorted;
    }

    std::vector<std::string> names() const {
        std::vector<std::string> result;
        for (const Entry* e : entries()) result.emplace_back(e->schema.name);
        return result;
    }

private:
    TypeRegistry() = default;
    std::vector<std::unique_ptr<Entry>> entries_;  // stable addresses for find()
};

// A static object whose construction registers `entry`: `const Registrar<MaterialType> r{{...}};`
template <class Entry>
struct Registrar {
    explicit Registrar(Entry entry) { TypeRegistry<Entry>::instance().add(std::move(entry)); }
};

}  // namespace lightpath

// A unique name per registrar (with __COUNTER__, not __LINE__: a unity build puts several
// registering files in one translation unit, where two registrations on the same line collided).
#define LIGHTPATH_SCHEMA_CONCAT_(a, b) a##b
#define LIGHTPATH_SCHEMA_CONCAT(a, b) LIGHTPATH_SCHEMA_CONCAT_(a, b)
