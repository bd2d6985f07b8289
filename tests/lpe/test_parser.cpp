// The parser: every class of error at its exact position, the limits, and a no-crash sweep.
#include <doctest/doctest.h>

#include <optional>
#include <random>
#include <string>
#include <vector>

#include "lpe/automaton.h"
#include "lpe/error.h"

namespace {

lpe::Automaton compileOne(const std::string& expression, const lpe::CompileOptions& options = {}) {
    return lpe::Automaton::compile({{"x", expression}}, options);
}

std::optional<lpe::SyntaxError> syntaxErrorOf(const std::string& expression) {
    try {
        compileOne(expression);
    } catch (const lpe::SyntaxError& e) {
        return e;
    }
    return std::nullopt;
}

struct ErrorCase {
    std::string expression;
    std::size_t position;
    std::string message;  // a substring of SyntaxError::message()
};

}  // namespace

TEST_CASE("syntax errors name what was expected, at the offending position") {
    const std::vector<ErrorCase> cases = {
        {"", 0, "expected an event (E, L, D, G, S, s, R, T, B, V, O, ., <...>, [...], '...') or '('"},
        {"   ", 3, "expected an event"},
        {"E(D|G L", 7, "expected ')' to close the group opened at column 2"},
        {"E((D)", 5, "expected ')' to close the group opened at column 2"},
        {"E()L", 2, "expected an event"},
        {"|E", 0, "expected an event"},
        {"E|", 2, "expected an event"},
        {"E||L", 2, "expected an event"},
        {"E(D|)L", 4, "expected an event"},
        {"ED)L", 2, "unmatched ')'"},
        {")", 0, "unmatched ')'"},
        {"*E", 0, "nothing to repeat before '*'"},
        {"E(+D)", 2, "nothing to repeat before '+'"},
        {"E|?", 2, "nothing to repeat before '?'"},
        {"{2}", 0, "nothing to repeat before '{'"},
        {"ED**L", 3, "nothing to repeat before '*'"},
        {"ED*?L", 3, "nothing to repeat before '?'"},
        {"ED{2}+L", 5, "nothing to repeat before '+'"},
        {"ED{2,1}L", 2, "repetition {2,1}: minimum 2 is greater than maximum 1"},
        {"ED{", 3, "expected a number after '{'"},
        {"ED{,3}L", 3, "expected a number after '{'"},
        {"ED{2L", 4, "expected '}' to close the repetition opened at column 3"},
        {"ED{2,3L", 6, "expected '}' to close the repetition opened at column 3"},
        {"E'key", 1, "unterminated label: expected a closing '"},
        {"E''L", 1, "empty label"},
        {"EXL", 1, "unknown event letter 'X'; expected an event"},
        {"E%L", 1, "unexpected '%'; expected an event"},
        {"E]", 1, "unexpected ']'"},
        {"E<X>", 2, "unknown event letter 'X' in tuple type position; expected one of E C R T L B V O . ["},
        {"E<<", 2, "unexpected '<' in tuple type position"},
        {"E<>", 2, "empty tuple"},
        {"E<RQ>", 3, "unknown scattering letter 'Q' in tuple scattering position"},
        {"E<RS", 4, "expected '>' to close the tuple opened at column 2"},
        {"E<RS D>", 5, "expected a quoted label or '>' to close the tuple opened at column 2"},
        {"E<[RX]>", 4, "unknown event letter 'X' in a tuple set; expected one of E C R T L B"},
        {"E<R[]>", 4, "empty set"},
        {"E<RD['a' D]>", 9, "expected a quoted label"},
        {"E[]L", 2, "empty set"},
        {"E[^]L", 3, "empty set"},
        {"E[DG", 4, "expected ']' to close the set opened at column 2 ([ ] of single events is OSL's set, "
                    "e.g. [SG]; [ ] holding an operator, a group or | is Heckbert's optional, e.g. [S*] = (S*)?)"},
        {"E[S*", 4, "expected ']' to close the optional group opened at column 2 ([ ] of single events is OSL's set"},
        {"E[S*)L", 4, "expected ']' to close the optional group opened at column 2"},
        {"E[(D])L", 4, "expected ')' to close the group opened at column 3"},
        {"E[^S*]L", 4, "unexpected '*'; a negated set [^...] holds single events"},
        {"ES]L", 2, "unexpected ']'"},
        {"E[D^G]", 3, "unexpected '^'"},
        {"ExL", 1, "'x' (no scattering) is a tuple position, as in OSL: write <Lx> or <.x>"},
        {"E[x]L", 2, "unknown event letter 'x'"},
        {"E<RZ'floor'>L", 3, "unknown scattering letter 'Z' in tuple scattering position; expected one of D G S s _ x"},
        {std::string("E\0L", 3), 1, "unexpected byte 0x00"},
        {"E\xC3\xA9L", 1, "unexpected byte 0xC3"},
    };
    for (const ErrorCase& c : cases) {
        CAPTURE(c.expression);
        const auto error = syntaxErrorOf(c.expression);
        REQUIRE(error.has_value());
        CHECK(error->position() == c.position);
        CHECK(error->message().find(c.message) != std::string::npos);
        CHECK(error->text() == c.expression);
        CHECK(std::string(error->what()).find(c.message) != std::string::npos);
    }
}

TEST_CASE("what() shows the message, the text and a caret under the offending character") {
    const auto error = syntaxErrorOf("E(D|G L");
    REQUIRE(error.has_value());
    CHECK(std::string(error->what()) ==
          "LPE syntax error at column 8: expected ')' to close the group opened at column 2\n"
          "  E(D|G L\n"
          "         ^");

    const auto repetition = syntaxErrorOf("ED{2,1}L");
    REQUIRE(repetition.has_value());
    CHECK(std::string(repetition->what()) ==
          "LPE syntax error at column 3: repetition {2,1}: minimum 2 is greater than maximum 1\n"
          "  ED{2,1}L\n"
          "    ^");

    // A multi-byte UTF-8 character takes one column: the caret stays under the culprit.
    const auto utf8 = syntaxErrorOf("E'\xC3\xA9t\xC3\xA9'X");
    REQUIRE(utf8.has_value());
    CHECK(utf8->position() == 8);
    CHECK(std::string(utf8->what()).substr(std::string(utf8->what()).rfind('\n') + 1) == "        ^");
}

TEST_CASE("well-formed corner cases parse") {
    for (const char* text : {"E D L", " E ( D | G ) L ", "ED{0}L", "ED{0,0}L", "ED{ 2 , 3 }L", "ED{2,}L",
                             "E<RS'a''b'>L", "E<L'key'>", "E<[RT][^D]>L", "E<.D['a' 'b']>L", "E<RD[^'a']>L",
                             "E[^<RS>'floor'D]L", "E<R.>L", "E<RD.>L", "C'x y'L", "(E)(((D)))L", "ED{256}L"}) {
        CAPTURE(text);
        CHECK_NOTHROW(compileOne(text));
    }
}

TEST_CASE("limits throw LimitError instead of hanging") {
    CHECK_THROWS_AS(compileOne("D{999999999999}"), lpe::LimitError);
    CHECK_THROWS_AS(compileOne("D{257}"), lpe::LimitError);
    CHECK_THROWS_AS(compileOne("D{1,300}"), lpe::LimitError);
    CHECK_THROWS_AS(compileOne("((D{200}){200}){200}"), lpe::LimitError);
    CHECK_THROWS_AS(compileOne(std::string(300, '(') + "D" + std::string(300, ')')), lpe::LimitError);
    CHECK_THROWS_AS(compileOne(std::string(10001, 'D')), lpe::LimitError);
    CHECK_NOTHROW(compileOne(std::string(10000, 'D')));

    // Subset construction of .*D.{n} needs 2^(n+1) states (the n-th event from the end is a D).
    lpe::CompileOptions small;
    small.maxStates = 1000;
    CHECK_THROWS_AS(compileOne(".*D.{30}", small), lpe::LimitError);
    CHECK_THROWS_AS(compileOne(".*D.{10}", small), lpe::LimitError);
    CHECK(compileOne(".*D.{8}", small).stateCount() == 512);

    std::vector<lpe::NamedExpression> many(65, {"x", "EL"});
    CHECK_THROWS_AS(lpe::Automaton::compile(many), lpe::LimitError);
    many.resize(64);
    CHECK(lpe::Automaton::compile(many).outputCount() == 64);
    lpe::CompileOptions rest;
    rest.complementName = "rest";
    CHECK_THROWS_AS(lpe::Automaton::compile(many, rest), lpe::LimitError);
}

namespace {

// Compiles `text`; fails the test on anything but success, SyntaxError or LimitError.
void parseOrThrowCleanly(const std::string& text) {
    lpe::CompileOptions options;
    options.maxStates = 2000;
    try {
        compileOne(text, options);
    } catch (const lpe::SyntaxError& e) {
        CHECK(e.position() <= text.size());
        CHECK(e.text() == text);
    } catch (const lpe::LimitError&) {
    } catch (const std::exception& e) {
        FAIL("unexpected exception " << e.what() << " for " << text);
    }
}

}  // namespace

TEST_CASE("random bytes and token soups either parse or throw SyntaxError or LimitError") {
    std::mt19937 rng(20240611);
    const std::string syntax = "ECLBDGSsRT._()|*+?{},<>[]^' 0123456789";
    for (int i = 0; i < 20000; ++i) {
        std::string text(std::uniform_int_distribution<int>(0, 24)(rng), '\0');
        for (char& c : text) {
            // Half the bytes from the expression syntax, half anything at all.
            c = rng() % 2 ? syntax[rng() % syntax.size()] : static_cast<char>(rng() % 256);
        }
        parseOrThrowCleanly(text);
    }

    const std::vector<std::string> tokens = {
        "E", "C", "L", "B", "D", "G", "S", "s", "R", "T", ".", "(", ")", "|", "*", "+", "?", "{2}", "{1,3}",
        "{0,}", "{999999999999}", "{2,1}", "{", "}", ",", "<", ">", "<RS>", "<TS>", "<L'key'>", "<L>", "[",
        "]", "[^", "[DG]", "[^D]", "'key'", "'", "''", "^", "_", " ", "<.", "<[RT]", "[^'a']>", "\xff", std::string(1, '\0')};
    for (int i = 0; i < 20000; ++i) {
        std::string text;
        const int count = std::uniform_int_distribution<int>(0, 12)(rng);
        for (int t = 0; t < count; ++t) text += tokens[rng() % tokens.size()];
        parseOrThrowCleanly(text);
    }
}
