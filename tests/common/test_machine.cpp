// The machine's columns of measured CSVs (machine.hpp): appended to the header and every row, quoted where a
// field needs it, read back by read_csv with the columns as its optional tail; this machine's own values.
#include "strahl/machine.hpp"
#include "strahl/program.hpp"
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <regex>

TEST_CASE("machine: with_machine adds the four columns to the header and to every row, not to empty lines", "[common]") {
    const strahl::machine_columns m{"AMD EPYC, 96 cores", "AVX512", "2026-12-05", 2};
    const std::string out = strahl::with_machine("a,b\n1,2\n\n3,4\n", m);
    CHECK(out == "a,b,cpu,threads,kernels,date\n1,2,\"AMD EPYC, 96 cores\",2,AVX512,2026-12-05\n\n"
                 "3,4,\"AMD EPYC, 96 cores\",2,AVX512,2026-12-05\n");
    CHECK(strahl::with_machine("", m).empty());
}

TEST_CASE("machine: a stamped file reads back with the columns as the format's tail", "[common]") {
    const auto dir = std::filesystem::temp_directory_path() / "strahl_test_machine";
    std::filesystem::create_directories(dir);
    const auto file = dir / "t.csv";
    std::ofstream(file) << "scene,mrays_s\nbunny,2.5\nsponza,1.25\n";
    strahl::stamp_machine(file, 1);
    const auto rows = strahl::read_csv(file, "scene,mrays_s", strahl::machine_header, "a test table");
    REQUIRE(rows.size() == 2);
    REQUIRE(rows[0].cells.size() == 6);
    CHECK(rows[0].cells[0] == "bunny");
    CHECK(!rows[0].cells[2].empty());  // the CPU's name
    CHECK(rows[1].cells[3] == "1");
    CHECK(std::regex_match(rows[1].cells[5], std::regex("[0-9]{4}-[0-9]{2}-[0-9]{2}")));
    std::filesystem::remove_all(dir);
    CHECK_THROWS_AS(strahl::stamp_machine(dir / "absent.csv", 1), std::runtime_error);
}

TEST_CASE("machine: this machine names its CPU, kernels and today", "[common]") {
    const strahl::machine_columns m = strahl::this_machine(3);
    CHECK(!m.cpu.empty());
    CHECK(!m.kernels.empty());
    CHECK(m.threads == 3);
    CHECK(std::regex_match(m.date, std::regex("20[0-9]{2}-[01][0-9]-[0-3][0-9]")));
}
