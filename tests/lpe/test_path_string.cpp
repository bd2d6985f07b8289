// Paths as text: both forms parse to hand-built events, print back, and fail at the right place.
#include <doctest/doctest.h>

#include <optional>
#include <random>
#include <string>

#include "lpe/error.h"
#include "lpe/path_string.h"
#include "test_paths.h"

using lpe::EventType;
using lpe::Scatter;
using lpe_test::event;

namespace {

std::optional<lpe::SyntaxError> errorOf(const std::string& text) {
    try {
        lpe::parsePath(text);
    } catch (const lpe::SyntaxError& e) {
        return e;
    }
    return std::nullopt;
}

}  // namespace

TEST_CASE("compact paths: one Heckbert letter per event") {
    CHECK(lpe::parsePath("ESDL") == lpe::Path{event(EventType::Camera),
                                              event(EventType::Reflection, Scatter::Specular),
                                              event(EventType::Reflection, Scatter::Diffuse),
                                              event(EventType::Emitter)});
    CHECK(lpe::parsePath("CGsRTB") == lpe::Path{event(EventType::Camera),
                                                event(EventType::Reflection, Scatter::Glossy),
                                                event(EventType::Reflection, Scatter::Straight),
                                                event(EventType::Reflection),
                                                event(EventType::Transmission),
                                                event(EventType::Background)});
    CHECK(lpe::parsePath("  EDL\n") == lpe::parsePath("EDL"));  // surrounding whitespace is not a separator
    CHECK(lpe::parsePath("").empty());
    CHECK(lpe::parsePath("   ").empty());
}

TEST_CASE("tuple paths: type, optional scattering, optional label, separated by spaces") {
    CHECK(lpe::parsePath("C TS TS RD'1' L'key'") ==
          lpe::Path{event(EventType::Camera), event(EventType::Transmission, Scatter::Specular),
                    event(EventType::Transmission, Scatter::Specular),
                    event(EventType::Reflection, Scatter::Diffuse, "1"),
                    event(EventType::Emitter, Scatter::None, "key")});
    CHECK(lpe::parsePath("E\tR_  Ts B") == lpe::Path{event(EventType::Camera), event(EventType::Reflection),
                                                     event(EventType::Transmission, Scatter::Straight),
                                                     event(EventType::Background)});
    // A quote alone selects the tuple form; D G S s alone are reflections there too.
    CHECK(lpe::parsePath("L'key light'") == lpe::Path{event(EventType::Emitter, Scatter::None, "key light")});
    CHECK(lpe::parsePath("E D'floor' L") ==
          lpe::Path{event(EventType::Camera), event(EventType::Reflection, Scatter::Diffuse, "floor"),
                    event(EventType::Emitter)});
}

TEST_CASE("printing: compact loses labels and R/T, tuples are lossless") {
    const lpe::Path path = {event(EventType::Camera), event(EventType::Reflection, Scatter::Specular),
                            event(EventType::Transmission, Scatter::Specular),
                            event(EventType::Reflection, Scatter::Diffuse, "floor"),
                            event(EventType::Emitter, Scatter::None, "key")};
    CHECK(lpe::toCompactString(path) == "ESSDL");
    CHECK(lpe::toTupleString(path) == "E RS TS RD'floor' L'key'");
    CHECK(lpe::toDisplayString(path) == "E RS TS RD'floor' L'key'");
    CHECK(lpe::toDisplayString({event(EventType::Camera), event(EventType::Reflection, Scatter::Glossy),
                                event(EventType::Background)}) == "EGB");
    CHECK(lpe::toCompactString({event(EventType::Reflection), event(EventType::Transmission)}) == "RT");
    CHECK(lpe::toTupleString({}).empty());
}

TEST_CASE("a lone two-letter word reads as compact: tuple strings need two events or a label") {
    CHECK(lpe::parsePath("RS") == lpe::Path{event(EventType::Reflection), event(EventType::Reflection, Scatter::Specular)});
    CHECK(lpe::parsePath("RS'x'") == lpe::Path{event(EventType::Reflection, Scatter::Specular, "x")});
    CHECK(lpe::parsePath("E") == lpe::Path{event(EventType::Camera)});
}

TEST_CASE("tuple strings round-trip for random paths") {
    std::mt19937 rng(42);
    const std::string labelCharacters = "abc xyz_-=.<>[]()019\xc3\xa9";
    for (int i = 0; i < 2000; ++i) {
        lpe::Path path(2 + rng() % 6);
        for (lpe::Event& e : path) {
            e.type = static_cast<EventType>(rng() % lpe::kEventTypeCount);
            e.scatter = static_cast<Scatter>(rng() % lpe::kScatterCount);
            if (rng() % 3 == 0) {
                e.label.resize(1 + rng() % 6);
                for (char& c : e.label) c = labelCharacters[rng() % labelCharacters.size()];
            }
        }
        CAPTURE(lpe::toTupleString(path));
        CHECK(lpe::parsePath(lpe::toTupleString(path)) == path);
        if (lpe::toDisplayString(path) != lpe::toTupleString(path)) {
            CHECK(lpe::parsePath(lpe::toDisplayString(path)) == path);
        }
    }
}

TEST_CASE("path errors name the position") {
    struct Case {
        std::string text;
        std::size_t position;
        std::string message;
    };
    for (const Case& c : std::vector<Case>{
             {"ESXL", 2, "unknown event letter 'X' in a path"},
             {"ES_L", 2, "unexpected '_' in a path"},
             {"E%", 1, "unexpected"},
             {"E RS X", 5, "unknown event type 'X' in a path"},
             {"E RQ L", 3, "expected a space before the next event"},
             {"E RDL", 4, "expected a space"},
             {"E L'key", 3, "unterminated label: expected a closing '"},
             {"E L''", 3, "empty label"},
             {"E L'a'b", 6, "expected a space"},
             {"E _ L", 2, "unexpected '_' in a path"},
         }) {
        CAPTURE(c.text);
        const auto error = errorOf(c.text);
        REQUIRE(error.has_value());
        CHECK(error->position() == c.position);
        CHECK(error->message().find(c.message) != std::string::npos);
        CHECK(std::string(error->what()).find("\n  " + c.text + "\n") != std::string::npos);
    }
}
