// The Catch2 main of every test binary, plus the grading listener.
//
// Grading: a test case tagged [pts:N] is worth N points. Its name starts with the exercise it grades,
// "NN.K name: what it checks" (e.g. "01.2 ray/sphere: hit in front"), and it carries the chapter tag [chNN].
// When the environment names STRAHL_GRADE_FILE, each graded test case appends one line to that file:
//   chapter <TAB> exercise <TAB> points <TAB> 1|0 (passed) <TAB> test case name
// A test case passes only if it made at least one assertion and none failed (an exception fails it).
// ./course grade adds these lines up.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace {

struct grading_listener : Catch::TestEventListenerBase {
    using TestEventListenerBase::TestEventListenerBase;

    void testCaseEnded(const Catch::TestCaseStats& stats) override {
        const char* file = std::getenv("STRAHL_GRADE_FILE");
        if (!file) return;
        int points = 0;
        std::string chapter = "??";
        for (const std::string& tag : stats.testInfo.tags) {
            if (tag.rfind("pts:", 0) == 0) points = std::atoi(tag.c_str() + 4);
            if (tag.size() == 4 && tag.rfind("ch", 0) == 0) chapter = tag.substr(2);
        }
        if (points <= 0) return;
        const std::string& name = stats.testInfo.name;
        const std::string exercise = name.substr(0, name.find(':'));
        const auto& a = stats.totals.assertions;
        const bool passed = a.failed == 0 && a.failedButOk == 0 && a.passed > 0;
        std::ofstream out(file, std::ios::app);
        out << chapter << '\t' << exercise << '\t' << points << '\t' << (passed ? 1 : 0) << '\t' << name << '\n';
    }
};

}  // namespace

CATCH_REGISTER_LISTENER(grading_listener)

// Floats and doubles print with every digit that tells them apart (9 and 17), so a failing comparison shows
// 9.99999975e-06f, not 0.0f (Catch2's default precision is 5 digits for float).
int main(int argc, char* argv[]) {
    Catch::StringMaker<float>::precision = 9;
    Catch::StringMaker<double>::precision = 17;
    return Catch::Session().run(argc, argv);
}
