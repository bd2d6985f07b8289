#include "cli/types_command.h"

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "config/exit_codes.h"
#include "film/aov_presets.h"
#include "integrators/registry.h"
#include "scene/light_type.h"
#include "scene/shape_type.h"
#include "materials/material_type.h"
#include "media/medium_type.h"
#include "scene/spelling.h"
#include "schema/markdown.h"

namespace lightpath {
namespace {

struct TypesOptions {
    std::string family;
    std::string name;
    bool markdown = false;
};

// One family's types in listing order, whatever the entry type of its registry.
struct Family {
    std::string_view name;
    std::string_view summary;
    std::vector<const TypeSchema*> (*types)();
};

template <class Entry>
std::vector<const TypeSchema*> schemasOf() {
    std::vector<const TypeSchema*> schemas;
    for (const Entry* entry : TypeRegistry<Entry>::instance().entries()) schemas.push_back(&entry->schema);
    return schemas;
}

const std::vector<Family>& families() {
    static const std::vector<Family> list = {
        {"material", "[materials.NAME] type = \"...\"", schemasOf<MaterialType>},
        {"medium", "[media.NAME] type = \"...\"", schemasOf<MediumType>},
        {"light", "[[lights]] type = \"...\"", schemasOf<LightType>},
        {"shape", "[[SECTION]] of a shape kind, e.g. [[disks]]", schemasOf<ShapeType>},
        {"integrator", "render --integrator ...", schemasOf<IntegratorInfo>},
        {"preset", "render --aovs ..., lpe check --set ..., serve's AOV menu", schemasOf<AovPreset>},
    };
    return list;
}

[[noreturn]] void unknown(std::string_view kind, const std::string& word, const std::vector<std::string>& known) {
    throw CLI::RuntimeError("types: " + unknownNameMessage(kind, word, known, ListKnown::always), kExitBadInput);
}

void listFamily(const Family& family) {
    std::cout << family.name << " (" << family.summary << ")\n";
    for (const TypeSchema* schema : family.types()) std::cout << "  " << schema->name << "  " << schema->summary << "\n";
}

void printType(const TypeSchema& schema, bool markdown) {
    if (markdown) {
        std::cout << markdownTable(schema);
        return;
    }
    std::cout << schema.family << " \"" << schema.name << "\": " << schema.summary << "\n";
    std::cout << "events: " << schema.events << "\n";
    if (schema.parameters.empty()) {
        std::cout << "parameters: none\n";
        return;
    }
    // The README's table without its Markdown.
    const auto plain = [](std::string text) {
        text.erase(std::remove(text.begin(), text.end(), '`'), text.end());
        return text;
    };
    std::cout << "parameters:\n";
    for (const Parameter& p : schema.parameters) {
        const std::string defaultValue = p.required ? "required" : p.defaultText.empty() ? "none" : std::string(p.defaultText);
        std::cout << "  " << p.name << "  " << typeName(p.type) << (p.unit.empty() ? "" : ", " + std::string(p.unit))
                  << "; default " << defaultValue << "; allowed " << plain(allowedText(p)) << "\n      "
                  << plain(std::string(p.doc)) << "\n";
    }
}

// A preset's AOVs, as `lpe check --set` reads them; one made from the scene says so.
void printPresetAovs(const TypeSchema& schema) {
    const AovPreset* preset = schema.family == "preset" ? findAovPreset(schema.name) : nullptr;
    if (!preset) return;
    if (preset->fromScene) {
        std::cout << "aovs: made from the scene (render --aovs " << schema.name << ", serve)\n";
        return;
    }
    std::cout << "aovs:\n";
    for (const lpe::NamedExpression& aov : preset->expressions()) std::cout << "  " << aov.name << "  " << aov.expression << "\n";
}

void runTypes(const TypesOptions& options) {
    if (options.family.empty()) {
        for (const Family& family : families()) listFamily(family);
        return;
    }
    std::vector<std::string> familyNames;
    for (const Family& family : families()) familyNames.emplace_back(family.name);
    const auto family = std::find_if(families().begin(), families().end(),
                                     [&](const Family& f) { return f.name == options.family; });
    if (family == families().end()) unknown("family", options.family, familyNames);
    if (options.name.empty()) {
        if (options.markdown) throw CLI::RuntimeError("types: --markdown needs a type: types FAMILY NAME --markdown", kExitBadInput);
        listFamily(*family);
        return;
    }
    std::vector<std::string> typeNames;
    for (const TypeSchema* schema : family->types()) {
        if (schema->name == options.name) {
            printType(*schema, options.markdown);
            if (!options.markdown) printPresetAovs(*schema);
            return;
        }
        typeNames.emplace_back(schema->name);
    }
    unknown(std::string(family->name) + " type", options.name, typeNames);
}

}  // namespace

void addTypesCommand(CLI::App& app) {
    auto options = std::make_shared<TypesOptions>();
    CLI::App* command = app.add_subcommand(
        "types", "List the material, light, shape, integrator and AOV preset types and, for one, its parameters and events");
    command->add_option("family", options->family, "material, light, shape, integrator or preset");
    command->add_option("name", options->name, "a type of that family, e.g. phong");
    command->add_flag("--markdown", options->markdown, "print the type's parameter table as scenes/README.md shows it");
    command->footer("Examples:\n  lightpath types\n  lightpath types light\n  lightpath types material phong --markdown");
    command->callback([options] { runTypes(*options); });
}

}  // namespace lightpath
