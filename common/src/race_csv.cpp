#include "strahl/race_csv.hpp"
#include "strahl/program.hpp"

namespace strahl {

std::vector<race_csv_row> read_race_rows(const std::filesystem::path& file) {
    std::vector<race_csv_row> rows;
    for (const csv_row& c : read_csv(file, race_csv_header, race_csv_machine_header,
                                     "a race.csv written by the race (chapter 16)")) {
        const auto number = [&](std::size_t k) { return c.cells[k].empty() ? 0.0 : csv_number(file, c, k); };
        race_csv_row r;
        r.scene = c.cells[0].substr(0, c.cells[0].find('.'));
        r.triangles = std::size_t(number(1));
        r.structure = c.cells[2], r.chapter = c.cells[3], r.rays = c.cells[5];
        r.ray_count = std::size_t(number(6));
        r.build_ms = number(7), r.memory_bytes = number(8);
        r.closest_mrays_s = number(10), r.closest_differing = std::size_t(number(16));
        r.closest_box_per_ray = number(13), r.closest_prim_per_ray = number(14), r.closest_nodes_per_ray = number(15);
        r.any_mrays_s = number(17), r.any_differing = std::size_t(number(22));
        r.any_box_per_ray = number(20), r.any_prim_per_ray = number(21);
        if (c.cells.size() > 23) r.cpu = c.cells[23];
        rows.push_back(std::move(r));
    }
    return rows;
}

}  // namespace strahl
