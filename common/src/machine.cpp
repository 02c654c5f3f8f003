// This machine's columns for measured CSVs (machine.hpp).
#include "strahl/machine.hpp"
#include "strahl/embree_report.hpp"
#include "strahl/program.hpp"
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace strahl {

machine_columns this_machine(int threads) {
    machine_columns m;
    std::ifstream cpu("/proc/cpuinfo");
    std::string line;
    m.cpu = "unknown CPU";
    while (std::getline(cpu, line))
        if (line.rfind("model name", 0) == 0) { m.cpu = line.substr(line.find(':') + 2); break; }
    m.kernels = embree_configuration().kernels.empty() ? "none" : embree_configuration().kernels;
    m.threads = threads;
    const std::time_t now = std::time(nullptr);
    char date[16];
    std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
    m.date = date;
    return m;
}

std::string with_machine(const std::string& csv, const machine_columns& m) {
    const std::string values = csv_field(m.cpu) + ',' + std::to_string(m.threads) + ',' + csv_field(m.kernels) + ',' +
                               csv_field(m.date);
    std::istringstream in(csv);
    std::string out, line;
    bool first = true;
    while (std::getline(in, line)) {
        if (!line.empty()) line += ',' + std::string(first ? machine_header : values);
        out += line + '\n';
        first = false;
    }
    return out;
}

void stamp_machine(const std::filesystem::path& csv, int threads) {
    std::ifstream in(csv, std::ios::binary);
    if (!in) throw std::runtime_error(csv.string() + ": cannot read it back to add the machine's columns");
    std::ostringstream text;
    text << in.rdbuf();
    in.close();
    write_text(csv, with_machine(text.str(), this_machine(threads)));
}

}  // namespace strahl
