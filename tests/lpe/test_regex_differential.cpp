// Differential test: on the compact alphabet {E, D, G, S, L} an LPE is an ordinary regular
// expression, so the automaton must agree with std::regex_match (ECMAScript) on the compact string
// of every path. Random expressions (fixed seed) use only syntax both dialects read alike.
#include <doctest/doctest.h>

#include <random>
#include <regex>
#include <string>
#include <vector>

#include "lpe/automaton.h"
#include "test_paths.h"
#include "../support/sanitizer.h"

namespace {

constexpr const char* kAlphabet = "EDGSL";

// libstdc++'s default std::regex executor backtracks: exponentially, when repetitions nest around
// expressions that can match nothing, as (((D?){1,3}){2,3})+ on DDLDLDS (minutes). Those are the
// expressions that test Thompson's epsilon moves hardest, so rather than avoid them the reference
// uses libstdc++'s polynomial executor (an extension flag): the same compiled ECMAScript regex,
// run breadth-first.
#if defined(__GLIBCXX__)
constexpr auto kReferenceFlags = std::regex::ECMAScript | std::regex_constants::__polynomial;
#else
constexpr auto kReferenceFlags = std::regex::ECMAScript;
#endif

// A random expression as its own little tree, so that paths can be sampled from it.

struct Expr {
    enum class Kind { Atom, Concat, Alternate, Repeat };
    Kind kind = Kind::Atom;
    std::string atom;      // "E", ".", "[DG]", "[^SL]"...
    std::vector<Expr> children;
    int min = 0, max = 0;  // Repeat; max < 0: unbounded
    bool parenthesised = false;

    bool atomAccepts(char c) const {
        if (atom == ".") return true;
        if (atom.size() == 1) return atom[0] == c;
        const bool negated = atom[1] == '^';
        const bool listed = atom.find(c, negated ? 2 : 1) != std::string::npos;
        return listed != negated;
    }
};

class Generator {
public:
    explicit Generator(std::mt19937& rng) : rng_(rng) {}

    Expr expression(int depth) {
        Expr e;
        const int choice = depth == 0 ? 0 : pick(0, 5);
        if (choice <= 1) {
            e.atom = atom();
        } else if (choice <= 3) {
            e.kind = choice == 2 ? Expr::Kind::Concat : Expr::Kind::Alternate;
            const int count = pick(2, 3);
            for (int i = 0; i < count; ++i) e.children.push_back(expression(depth - 1));
        } else {
            e.kind = Expr::Kind::Repeat;
            switch (pick(0, 5)) {
                case 0: e.min = 0; e.max = -1; break;                          // *
                case 1: e.min = 1; e.max = -1; break;                          // +
                case 2: e.min = 0; e.max = 1; break;                           // ?
                case 3: e.min = e.max = pick(0, 3); break;                     // {n}
                case 4: e.min = pick(0, 2); e.max = -1; break;                 // {n,}
                default: e.min = pick(0, 2); e.max = e.min + pick(0, 2); break; // {n,m}
            }
            e.children.push_back(expression(depth - 1));
        }
        e.parenthesised = pick(0, 7) == 0;
        return e;
    }

    // A string of the expression's language, or false when a set matches no letter of the alphabet.
    bool sample(const Expr& e, std::string& out) {
        switch (e.kind) {
            case Expr::Kind::Atom: {
                std::string letters;
                for (const char* c = kAlphabet; *c; ++c) {
                    if (e.atomAccepts(*c)) letters += *c;
                }
                if (letters.empty()) return false;
                out += letters[pick(0, static_cast<int>(letters.size()) - 1)];
                return true;
            }
            case Expr::Kind::Concat:
                for (const Expr& child : e.children) {
                    if (!sample(child, out)) return false;
                }
                return true;
            case Expr::Kind::Alternate:
                return sample(e.children[pick(0, static_cast<int>(e.children.size()) - 1)], out);
            case Expr::Kind::Repeat: {
                const int count = pick(e.min, e.max < 0 ? e.min + 2 : e.max);
                for (int i = 0; i < count; ++i) {
                    if (!sample(e.children.front(), out)) return false;
                }
                return true;
            }
        }
        return false;
    }

    std::string randomPath() {
        std::string path(pick(0, 8), ' ');
        for (char& c : path) c = kAlphabet[pick(0, 4)];
        return path;
    }

    int pick(int low, int high) { return std::uniform_int_distribution<int>(low, high)(rng_); }

private:
    std::string atom() {
        if (pick(0, 5) > 0) return std::string(1, ".EDGSL"[pick(0, 5)]);
        std::string set = pick(0, 1) ? "[^" : "[";
        const int count = pick(1, 3);
        for (int i = 0; i < count; ++i) set += kAlphabet[pick(0, 4)];
        return set + "]";
    }

    std::mt19937& rng_;
};

// The text of an expression, valid and equal in meaning for both the LPE parser and ECMAScript.
std::string print(const Expr& e) {
    std::string text;
    switch (e.kind) {
        case Expr::Kind::Atom: text = e.atom; break;
        case Expr::Kind::Concat:
            for (const Expr& child : e.children) {
                const bool wrap = child.kind == Expr::Kind::Alternate && !child.parenthesised;
                text += wrap ? "(" + print(child) + ")" : print(child);
            }
            break;
        case Expr::Kind::Alternate:
            for (const Expr& child : e.children) text += (text.empty() ? "" : "|") + print(child);
            break;
        case Expr::Kind::Repeat: {
            const Expr& child = e.children.front();
            const bool wrap = child.kind != Expr::Kind::Atom && !child.parenthesised;
            text = wrap ? "(" + print(child) + ")" : print(child);
            if (e.min == 0 && e.max < 0) text += "*";
            else if (e.min == 1 && e.max < 0) text += "+";
            else if (e.min == 0 && e.max == 1) text += "?";
            else if (e.max < 0) text += "{" + std::to_string(e.min) + ",}";
            else if (e.min == e.max) text += "{" + std::to_string(e.min) + "}";
            else text += "{" + std::to_string(e.min) + "," + std::to_string(e.max) + "}";
            break;
        }
    }
    return e.parenthesised ? "(" + text + ")" : text;
}

// About twenty paths per expression: sampled from it (mostly matching), one-letter mutations of
// those (near misses), and uniformly random strings.
std::vector<std::string> pathsFor(const Expr& e, Generator& generator) {
    std::vector<std::string> paths;
    for (int i = 0; i < 8; ++i) {
        std::string sampled;
        if (generator.sample(e, sampled) && sampled.size() <= 10) {
            paths.push_back(sampled);
            if (!sampled.empty() && i % 2 == 0) {
                sampled[generator.pick(0, static_cast<int>(sampled.size()) - 1)] = kAlphabet[generator.pick(0, 4)];
                paths.push_back(sampled);
            }
        }
    }
    while (paths.size() < 20) paths.push_back(generator.randomPath());
    return paths;
}

}  // namespace

TEST_CASE("10,000 random expressions agree with std::regex_match on the compact string") {
    std::mt19937 rng(1968);  // Thompson's year
    Generator generator(rng);
    int matched = 0, checked = 0;
    // Agreement is proven over all 10,000 in the Release build; the sanitizer stage runs the same
    // parse, compile and match on the first 2,000 for their memory errors (support/sanitizer.h).
    const int expressions = lightpath::test::sanitizedCount(10000);
    for (int i = 0; i < expressions; ++i) {
        const Expr e = generator.expression(generator.pick(1, 4));
        const std::string text = print(e);
        const std::regex reference(text, kReferenceFlags);
        const lpe::Automaton automaton = lpe::Automaton::compile({{"x", text}});
        for (const std::string& path : pathsFor(e, generator)) {
            const bool expected = std::regex_match(path, reference);
            if (automaton.matches(lpe_test::compactPath(path), 0) != expected) {
                FAIL_CHECK("expression " << text << " on path \"" << path << "\": std::regex says " << expected);
            }
            matched += expected;
            ++checked;
        }
    }
    // The sampled paths must make the test exercise acceptance, not only rejection.
    CHECK(checked >= 20 * expressions);
    CHECK(matched > checked / 5);
}

TEST_CASE("several random expressions compiled together: every output bit agrees with its regex") {
    std::mt19937 rng(1971);  // Hopcroft's year
    Generator generator(rng);
    const std::regex universe("E.*L");
    for (int group = 0; group < 300; ++group) {
        std::vector<Expr> exprs;
        std::vector<lpe::NamedExpression> named;
        std::vector<std::regex> references;
        const int count = generator.pick(2, 8);
        for (int i = 0; i < count; ++i) {
            exprs.push_back(generator.expression(generator.pick(1, 4)));
            named.push_back({"out" + std::to_string(i), print(exprs.back())});
            references.emplace_back(named.back().expression, kReferenceFlags);
        }
        lpe::CompileOptions options;
        options.complementName = "rest";
        options.universe = "E.*L";
        const lpe::Automaton automaton = lpe::Automaton::compile(named, options);
        REQUIRE(automaton.outputCount() == named.size() + 1);

        std::vector<std::string> paths;
        for (const Expr& e : exprs) {
            for (const std::string& p : pathsFor(e, generator)) paths.push_back(p);
        }
        for (const std::string& path : paths) {
            const lpe::OutputMask got = automaton.run(lpe_test::compactPath(path));
            bool any = false;
            for (std::size_t i = 0; i < named.size(); ++i) {
                const bool expected = std::regex_match(path, references[i]);
                any = any || expected;
                if (((got >> i) & 1u) != expected) {
                    FAIL_CHECK("output " << named[i].expression << " on \"" << path << "\": std::regex says "
                                         << expected);
                }
            }
            const bool rest = std::regex_match(path, universe) && !any;
            if (((got >> named.size()) & 1u) != rest) {
                FAIL_CHECK("complement on \"" << path << "\": expected " << rest);
            }
        }
    }
}
