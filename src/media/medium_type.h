#pragma once
// A medium type a scene names with `[media.NAME] type = "..."`: its schema and how to make it from
// checked values, as materials are (materials/material_type.h). Each medium's .cpp registers its
// own with LIGHTPATH_REGISTER_MEDIUM.
#include "media/medium.h"
#include "schema/parameter_values.h"
#include "schema/registry.h"

namespace lightpath {

struct MediumType {
    TypeSchema schema;
    int rank = 0;  // listing order; rank 0 is the default type
    // May refuse a combination with values.fail(key, ...); the loader sets the name.
    MediumSlot (*make)(const ParameterValues& values) = nullptr;
};

using MediumRegistry = TypeRegistry<MediumType>;

}  // namespace lightpath

#define LIGHTPATH_REGISTER_MEDIUM(...) \
    namespace { const ::lightpath::Registrar<::lightpath::MediumType> LIGHTPATH_SCHEMA_CONCAT(kMediumRegistrar, __COUNTER__){__VA_ARGS__}; }
