// Unit tests of program.hpp: the command line (CLI11 behind the cli class, the shared options and scene names),
// --threads, the memory check, the output rule, STRAHL_TODO with guarded_main, and reading CSV files back.
#include <catch2/catch.hpp>
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/scene.hpp"
#include "strahl/todo.hpp"
#include "test_support.hpp"
#include <cstdlib>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

using namespace strahl;
using Catch::Matchers::Contains;

TEST_CASE("cli: options, flags, defaults, --help and clear errors", "[common][cli]") {
    auto make = [] {
        cli c("prog", "Does things.");
        c.option("width", "W", "640", "image width").option("scale", "S", "1.5", "scale").flag("quick", "be quick");
        return c;
    };
    {
        cli c = make();
        const char* argv[] = {"prog", "--width", "320", "--scale=2.25", "--quick"};
        REQUIRE(c.parse(5, argv));
        CHECK(c.get_int("width") == 320);
        CHECK(c.get_double("scale") == 2.25);
        CHECK(c.has("quick"));
        CHECK(c.has("width"));
    }
    {
        cli c = make();
        const char* argv[] = {"prog"};
        REQUIRE(c.parse(1, argv));
        CHECK(c.get_int("width") == 640);
        CHECK_FALSE(c.has("quick"));
        CHECK_FALSE(c.has("width"));
        CHECK_THAT(c.usage(), Contains("--width W") && Contains("(default: 640)") && Contains("--help"));
    }
    {
        cli c = make();
        const char* argv[] = {"prog", "--help"};
        CHECK_FALSE(c.parse(2, argv));
    }
    auto fails = [&](std::vector<const char*> args, const std::string& what) {
        cli c = make();
        args.insert(args.begin(), "prog");
        CHECK_THROWS_WITH(c.parse(int(args.size()), args.data()) && (c.get_int("width"), c.get_double("scale"), true),
                          Contains(what));
    };
    fails({"--nope"}, "unknown option --nope");
    fails({"--width"}, "needs a value");
    fails({"--width", "12x"}, "expects an integer");
    fails({"--width", "99999999999"}, "expects an integer");
    fails({"--width", "99999999999"}, "out of range");
    fails({"--scale", "nan"}, "expects a finite number");
    fails({"--scale", "1e999"}, "out of range");
    fails({"--scale", "1e-999"}, "out of range");
    {
        // A subnormal is a number like any other.
        cli c = make();
        const char* argv[] = {"prog", "--scale", "4e-320"};
        REQUIRE(c.parse(3, argv));
        CHECK(c.get_double("scale") == 4e-320);
    }
    fails({"--quick=1"}, "takes no value");
    fails({"stray"}, "unexpected argument");
}

TEST_CASE("cli: the shared options (--out with --force, --threads, --scene) and the scene names", "[common][cli]") {
    const auto make = [] {
        cli c("prog", "Does things.");
        c.scene_option({"stadium", "bunny", "teapot"}, {"stadium", "bunny"}, "the meshes where present")
            .threads_option("0", "worker threads")
            .output_options("write x.csv into DIR/");
        return c;
    };
    const auto names = [&](std::vector<const char*> args) {
        cli c = make();
        args.insert(args.begin(), "prog");
        REQUIRE(c.parse(int(args.size()), args.data()));
        return c.scene_names();
    };
    CHECK(names({}) == std::vector<std::string>{"stadium", "bunny"});
    CHECK(names({"--scene", "teapot"}) == std::vector<std::string>{"teapot"});
    CHECK_THROWS_WITH(names({"--scene", "sponza"}), Contains("--scene must be stadium, bunny, teapot or all, not 'sponza'"));
    cli c = make();
    CHECK_THAT(c.usage(), Contains("--scene NAME") && Contains("stadium, bunny, teapot or all (all: stadium, bunny; the "
                                                               "meshes where present)") &&
                              Contains("--out DIR") && Contains("--force") && Contains("--threads N"));
    const char* argv[] = {"prog", "--out", "somewhere", "--force", "--threads", "3"};
    REQUIRE(c.parse(6, argv));
    CHECK(c.get("out") == "somewhere");
    CHECK(c.has("force"));
    CHECK(c.get_int("threads") == 3);
    CHECK(course_scene("stadium")->name == "teapot_stadium");
    CHECK(course_scene("teapot")->mesh.triangle_count() > 0);
}

static int throws_usage(int, const char* const*) { throw usage_error("bad flag"); }
static int throws_todo(int, const char* const*) { STRAHL_TODO("01.2 ray/sphere"); }
static int throws_other(int, const char* const*) { throw std::runtime_error("disk full"); }
static int returns_zero(int, const char* const*) { return 0; }

TEST_CASE("STRAHL_TODO names the exercise, file and line, guarded_main maps errors to exit codes", "[common][todo]") {
    try {
        STRAHL_TODO("05.2 bin the centroids");
    } catch (const not_implemented& e) {
        CHECK(e.id() == "05.2 bin the centroids");
        CHECK_THAT(e.what(), Contains("exercise 05.2 (bin the centroids) is not done yet: tests/common/test_program.cpp:"));
        CHECK(e.line() > 0);
    }
    const char* argv[] = {"prog"};
    CHECK(guarded_main("prog", throws_usage, 1, argv) == 2);
    CHECK(guarded_main("prog", throws_todo, 1, argv) == 3);
    CHECK(guarded_main("prog", throws_other, 1, argv) == 1);
    CHECK(guarded_main("prog", returns_zero, 1, argv) == 0);
}

TEST_CASE("read_threads: --threads within [lo, 1024], a clear error beyond", "[common][cli]") {
    const auto threads = [](const char* value, int lo) {
        cli c("prog", "Does things.");
        c.option("threads", "N", "0", "threads");
        const char* argv[] = {"prog", "--threads", value};
        REQUIRE(c.parse(3, argv));
        return read_threads(c, lo);
    };
    CHECK(threads("0", 0) == 0);
    CHECK(threads("1024", 1) == 1024);
    CHECK_THROWS_WITH(threads("2147483647", 1), Contains("--threads must lie in [1, 1024], not 2147483647") &&
                                                    Contains("hardware threads"));
    CHECK_THROWS_WITH(threads("1025", 0), Contains("[0, 1024] (0: one per core)"));
    CHECK_THROWS_WITH(threads("0", 1), Contains("[1, 1024]"));
    CHECK_THROWS_AS(threads("-1", 0), usage_error);
}

TEST_CASE("check_memory: work needing more memory than there is is refused, saying how much", "[common][memory]") {
    CHECK(available_memory() > 0);
    CHECK_NOTHROW(check_memory(1 << 20, "a small image"));
    setenv("STRAHL_MEMORY_LIMIT_MB", "512", 1);
    CHECK(available_memory() <= (std::uint64_t(512) << 20));
    CHECK_NOTHROW(check_memory(std::uint64_t(100) << 20, "a small image"));
    CHECK_THROWS_WITH(check_memory(std::uint64_t(17) << 30, "a 16384 x 16384 image"),
                      Contains("a 16384 x 16384 image: about 17.0 GiB of memory needed, but only 512 MiB available"));
    setenv("STRAHL_MEMORY_LIMIT_MB", "lots", 1);
    CHECK_THROWS_WITH(available_memory(), Contains("STRAHL_MEMORY_LIMIT_MB") && Contains("'lots'"));
    unsetenv("STRAHL_MEMORY_LIMIT_MB");
}

TEST_CASE("prepare_output: creates folders, never overwrites a user's file unasked", "[common][output]") {
    const auto dir = test::scratch_dir("prepare_output");
    const auto nested = dir / "a" / "b" / "image.png";
    REQUIRE_NOTHROW(prepare_output(nested, true, false));
    CHECK(std::filesystem::is_directory(nested.parent_path()));

    std::ofstream(dir / "mine.png") << "precious";
    CHECK_THROWS_WITH(prepare_output(dir / "mine.png", true, false), Contains("not overwriting") && Contains("--force"));
    CHECK_NOTHROW(prepare_output(dir / "mine.png", true, true));
    CHECK_NOTHROW(prepare_output(dir / "mine.png", false, false));  // the course's own output: regenerated
    CHECK_THROWS_WITH(prepare_output(dir, true, true), Contains("is a folder"));
    std::ofstream(dir / "file") << "x";
    CHECK_THROWS_WITH(prepare_output(dir / "file" / "x.png", false, false), Contains("cannot create folder"));
    if (geteuid() != 0) {  // root may write anywhere
        std::filesystem::create_directories(dir / "locked");
        chmod((dir / "locked").c_str(), 0500);
        CHECK_THROWS_WITH(prepare_output(dir / "locked" / "x.png", false, false), Contains("permission denied"));
        chmod((dir / "locked").c_str(), 0700);
        // A read-only file is found before the work, --force or not.
        std::ofstream(dir / "read_only.png") << "x";
        chmod((dir / "read_only.png").c_str(), 0400);
        CHECK_THROWS_WITH(prepare_output(dir / "read_only.png", true, true),
                          Contains("cannot replace") && Contains("read-only"));
        CHECK_THROWS_WITH(prepare_output(dir / "read_only.png", false, false), Contains("cannot replace"));
    }
    // A symbolic link to nothing: not written through (its target would be created wherever it points).
    std::filesystem::create_symlink(dir / "nowhere" / "target.png", dir / "dangling.png");
    CHECK_THROWS_WITH(prepare_output(dir / "dangling.png", true, true),
                      Contains("is a symbolic link to") && Contains("which does not exist"));
    CHECK_FALSE(std::filesystem::exists(dir / "nowhere"));
    // A link to an existing file is that file: replaced with --force, as the user asked.
    std::filesystem::create_symlink(dir / "mine.png", dir / "link.png");
    CHECK_THROWS_WITH(prepare_output(dir / "link.png", true, false), Contains("not overwriting"));
    CHECK_NOTHROW(prepare_output(dir / "link.png", true, true));
}

TEST_CASE("read_csv and csv_number: a program's own table back, anything else refused with file and line",
          "[common][csv]") {
    const auto dir = test::scratch_dir("read_csv");
    const std::string header = "scene,ms,count";
    const auto file = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return dir / name;
    };
    const auto good = file("good.csv", header + "\nbunny,1.5,3\n\nsponza,0,12\n");
    const std::vector<csv_row> rows = read_csv(good, header, "a test table");
    REQUIRE(rows.size() == 2);  // the blank line skipped
    CHECK(rows[0].line == 2);
    CHECK(rows[1].line == 4);
    CHECK(rows[1].cells == std::vector<std::string>{"sponza", "0", "12"});
    CHECK(csv_number(good, rows[0], 1) == 1.5);
    CHECK(csv_number(good, rows[1], 2) == 12.0);

    CHECK_THROWS_WITH(read_csv(dir / "absent.csv", header, "a test table"), Contains("cannot read"));
    CHECK_THROWS_WITH(read_csv(file("foreign.csv", "a,b\n1,2\n"), header, "a test table"),
                      Contains("is not a test table") && Contains(header));
    CHECK_THROWS_WITH(read_csv(file("empty.csv", ""), header, "a test table"), Contains("is not a test table"));
    CHECK_THROWS_WITH(read_csv(file("rowless.csv", header + "\n"), header, "a test table"), Contains("holds no rows"));
    CHECK_THROWS_WITH(read_csv(file("short.csv", header + "\nbunny,1\n"), header, "a test table"),
                      Contains("line 2") && Contains("3 fields expected, not 2"));
    CHECK_THROWS_WITH(read_csv(file("trailing.csv", header + "\nbunny,1,2,\n"), header, "a test table"),
                      Contains("not 4"));

    // Quoted fields (RFC 4180): commas, doubled quotes and line breaks inside them come back whole.
    const std::vector<std::string> names = {"plain", "a,b", "say \"hi\"", "two\nlines", "", ",\""};
    std::string quoted = header + "\n";
    for (const std::string& n : names) quoted += csv_field(n) + ",1," + csv_field(n) + "\n";
    CHECK(csv_field("plain") == "plain");
    CHECK(csv_field("a,b") == "\"a,b\"");
    CHECK(csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
    const std::vector<csv_row> q = read_csv(file("quoted.csv", quoted), header, "a test table");
    REQUIRE(q.size() == names.size());
    for (std::size_t i = 0; i < names.size(); ++i) CHECK(q[i].cells == std::vector<std::string>{names[i], "1", names[i]});
    CHECK(q[4].line == 8);  // the row after the one that ran over lines 5 to 7
    CHECK_THROWS_WITH(read_csv(file("open.csv", header + "\n\"bunny,1,2\n"), header, "a test table"),
                      Contains("line 2") && Contains("not closed"));
    CHECK_THROWS_WITH(read_csv(file("after.csv", header + "\n\"bunny\"x,1,2\n"), header, "a test table"),
                      Contains("line 2") && Contains("follows its closing quote"));

    const auto bad = file("bad.csv", header + "\nx,nan,3\nx,-1,3\nx,1.5ms,3\nx,,3\nx,inf,1e400\n");
    const std::vector<csv_row> b = read_csv(bad, header, "a test table");
    REQUIRE(b.size() == 5);
    for (const csv_row& r : b) CHECK_THROWS_WITH(csv_number(bad, r, 1), Contains("line " + std::to_string(r.line)) &&
                                                                            Contains("is not a number >= 0"));
    CHECK_THROWS_WITH(csv_number(bad, b[4], 2), Contains("'1e400'") && Contains("is out of range"));

    // A subnormal is a number; a number beyond double's range in either direction is out of range.
    const auto tiny = file("tiny.csv", header + "\nx,4e-320,1e-400\n");
    const std::vector<csv_row> t = read_csv(tiny, header, "a test table");
    CHECK(csv_number(tiny, t[0], 1) == 4e-320);
    CHECK_THROWS_WITH(csv_number(tiny, t[0], 2), Contains("'1e-400' is out of range"));
}
