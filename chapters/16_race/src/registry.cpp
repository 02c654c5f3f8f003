#include "strahl/race/registry.hpp"
#include "strahl/race/brute_force.hpp"
#include "strahl/race/embree_accel.hpp"
#include "strahl/race/oo_tracer.hpp"
#include "strahl/ch02/accel.hpp"
#include "strahl/ch03/accel.hpp"
#include "strahl/ch04/accel.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch06/accel.hpp"
#include "strahl/ch07/accel.hpp"
#include "strahl/ch08/accel.hpp"
#include "strahl/ch09/accel.hpp"
#include "strahl/ch10/accel.hpp"
#include "strahl/ch11/steps.hpp"
#include "strahl/ch12/accel.hpp"
#include "strahl/ch13/accel.hpp"
#include "strahl/ch14/accel.hpp"
#include "strahl/ch15/accel.hpp"
#include <algorithm>
#include <optional>
#include <tuple>
#include <stdexcept>

namespace strahl::race {

namespace {
ch05::sah_build_params sah(ch05::sah_method m, int bins) {
    ch05::sah_build_params p;
    p.method = m;
    if (bins > 0) p.bins = bins;
    return p;
}
ch06::refine_params refined(ch06::start_tree start, ch06::refine_method method) {
    ch06::refine_params p;
    p.start = start;
    p.method = method;
    return p;
}
// Chapter 07: an LBVH walked by chapter 05's fast traversal.
accel_entry lbvh(std::string name, std::string description, ch07::hierarchy_method h, int bits_per_axis) {
    ch07::lbvh_params p;
    p.hierarchy = h, p.bits_per_axis = bits_per_axis;
    return {std::move(name), "07", std::move(description), [p] { return std::unique_ptr<accel>(ch07::make_accel(p)); }};
}
// Chapter 11: one step of devirtualization over chapter 05's binned SAH tree and fast walk.
accel_entry ch11_step(ch11::step s) {
    const ch11::step_info& i = ch11::info(s);
    return {std::string("ch11-") + i.name, "11", std::string("chapter 05's binned SAH tree, fast walk; ") + i.what,
            [s] { return std::unique_ptr<accel>(ch11::make_accel(s)); }};
}
// Chapter 13: chapter 05's fast binned tree (or chapter 06's reinserted one) collapsed into a wide tree.
accel_entry wide(std::string name, std::string description, int width, int block, ch13::collapse_method method,
                 bool reinserted = false, bool watertight = false,
                 ch13::child_order order = ch13::child_order::collapsed, bool quantized = false, bool octant = false) {
    ch13::wide_config c;
    c.width = width, c.block = block, c.collapse.method = method, c.watertight = watertight, c.order = order;
    c.quantized = quantized, c.octant_order = octant;
    const ch04::bvh_builder source = reinserted
        ? ch04::bvh_builder([](std::span<const aabb> b, std::span<const vec3> centroids) {
              return ch06::build_refined_bvh(b, centroids, refined(ch06::start_tree::binned16, ch06::refine_method::reinsertion));
          })
        : ch04::bvh_builder([](std::span<const aabb> b, std::span<const vec3> centroids) {
              return ch05::build_sah_bvh_fast(b, centroids, sah(ch05::sah_method::binned, 16));
          });
    return {name, "13", std::move(description), [name, source, c] { return ch13::make_accel(name, source, c); }};
}
// Chapter 12: a packet tracer, rays grouped in tiles of the race's image (registry_options::packet_width).
accel_entry packets(ch12::walk_kind walk, int lanes, int tile_w, int tile_h, int image_width) {
    const ch12::packet_config c{walk, lanes, tile_w, tile_h, image_width};
    const std::string name = std::string("ch12-") + ch12::to_string(walk) + std::to_string(lanes) + "-" +
                             std::to_string(tile_w) + "x" + std::to_string(tile_h);
    const bool wide = walk == ch12::walk_kind::wide || walk == ch12::walk_kind::frustum;
    const std::string tree = wide ? "chapter 13's 8-wide tree (optimal collapse)" : "chapter 05's binned SAH tree";
    return {name, "12", "packets: " + ch12::describe(c) + ", " + tree,
            [name, c] { return std::unique_ptr<accel>(ch12::make_accel(name, c)); }};
}
// Chapter 14: the hybrid tracer, K-ray packets (tiles of the race's image) on chapter 13's 8-wide tree, rays
// leaving for the single-ray walk at `threshold` active lanes (ch14::automatic: per packet); strict: boxes
// tested from tmin (not exact, "-strict").
accel_entry hybrid(int lanes, int threshold, int image_width, bool strict = false, bool stored = false,
                   std::string name = "") {
    const ch14::hybrid_config c{lanes, 4, lanes / 4, image_width, threshold, strict,
                                stored ? ch13::child_order::collapsed : ch13::child_order::leaves_then_area};
    if (name.empty())
        name = "ch14-hybrid" + std::to_string(lanes) + "-" + ch14::threshold_name(threshold) + (strict ? "-strict" : "") +
               (stored ? "-stored" : "");
    return {name, "14", ch14::describe(c) + "; chapter 13's 8-wide tree (optimal collapse, blocks of 8)",
            [name, c] { return ch14::make_accel(name, c); }};
}
// The course's final tracer, one named row: the 16-lane hybrid with the threshold per packet, as
// ch14-hybrid16-auto (its tree from chapter 05's binned SAH, chosen for its build time; any hit leaves first).
// With sbvh, the same tracer on chapter 09's SBVH (spatial splits): its slower build, measured beside it.
accel_entry final_tracer(int image_width, bool sbvh = false) {
    ch14::hybrid_config c{16, 4, 4, image_width, ch14::automatic, false, ch13::child_order::leaves_then_area};
    c.octant_order = true;
    if (sbvh) c.builder = [](const triangle_mesh& m) { return ch09::build_sbvh(m); };
    const std::string name = sbvh ? "final-sbvh" : "final";
    return {name, "14",
            (sbvh ? "the final tracer on chapter 09's SBVH (spatial splits): " : "the course's final tracer: ") +
                ch14::describe(c) + "; chapter 13's 8-wide tree (optimal collapse, blocks of 8)" +
                (sbvh ? "" : " from chapter 05's binned SAH tree"),
            [name, c] { return ch14::make_accel(name, c); }};
}
// Chapter 13's wide walk over another chapter's tree: N-wide nodes (optimal collapse), blocks of M.
ch13::wide_config wide_optimal(int width, int block) {
    ch13::wide_config c;
    c.width = width, c.block = block, c.collapse.method = ch13::collapse_method::optimal;
    return c;
}
}  // namespace

std::vector<accel_entry> registered_accels(const registry_options& o) {
    std::vector<accel_entry> list = {
        {"brute", "16", "brute force: every triangle, chapter 01's triangle test (the reference)",
         [] { return std::make_unique<brute_force>(); }, true},
        {"ch01-virtual", "01", "chapter 01's object-oriented tracer: a virtual call per triangle, brute force",
         [] { return make_oo_tracer(); }, true},
        {"ch02-grid", "02", "uniform grid, 3D-DDA with mailboxing, over plain triangles", [] { return ch02::make_accel(false); }},
        {"ch02-grid-virtual", "02", "the same grid over chapter 01's virtual objects", [] { return ch02::make_accel(true); }},
        {"ch03-kd", "03", "SAH k-d tree, front-to-back traversal, over plain triangles", [] { return ch03::make_accel(false); }},
        {"ch03-kd-virtual", "03", "the same k-d tree over chapter 01's virtual objects", [] { return ch03::make_accel(true); }},
        {"ch04-median", "04", "BVH, object median split, near-first traversal, over plain triangles",
         [] { return ch04::make_accel(false, ch04::split_method::object_median); }},
        {"ch04-median-virtual", "04", "the same BVH over chapter 01's virtual objects",
         [] { return ch04::make_accel(true, ch04::split_method::object_median); }},
        {"ch04-median-fast", "04", "the same object-median BVH walked by chapter 05's faster scalar traversal "
         "(chapter 08's build/trace plot compares every builder under that walk)",
         [] {
             return ch05::make_bvh_accel(false, "ch04-median-fast", [](std::span<const aabb> b, std::span<const vec3> c) {
                 ch04::bvh_build_params p;
                 p.split = ch04::split_method::object_median;
                 return ch04::build_bvh(b, c, p);
             }, ch05::walk_kind::fast);
         }},
        {"ch04-spatial", "04", "BVH, spatial median split, over plain triangles",
         [] { return ch04::make_accel(false, ch04::split_method::spatial_median); }},
        {"ch05-sweep", "05", "BVH, full SAH sweep over sorted centroids, chapter 04's traversal",
         [] { return ch05::make_accel(false, sah(ch05::sah_method::sweep, 0)); }},
        {"ch05-binned16", "05", "BVH, binned SAH with 16 bins per axis, chapter 04's traversal",
         [] { return ch05::make_accel(false, sah(ch05::sah_method::binned, 16)); }},
        {"ch05-binned16-virtual", "05", "the same over chapter 01's virtual objects",
         [] { return ch05::make_accel(true, sah(ch05::sah_method::binned, 16)); }},
        {"ch05-binned16-fast", "05", "the same tree from chapter 05's fast builder, walked by its faster scalar traversal",
         [] { return ch05::make_accel(false, sah(ch05::sah_method::binned, 16), ch05::walk_kind::fast); }},
        {"ch06-median-rotated", "06", "chapter 04's median BVH refined by tree rotations (Kensler 2008)",
         [] { return ch06::make_accel(false, refined(ch06::start_tree::median, ch06::refine_method::rotations)); }},
        {"ch06-binned16-rotated", "06", "chapter 05's binned SAH BVH (16 bins) refined by tree rotations",
         [] { return ch06::make_accel(false, refined(ch06::start_tree::binned16, ch06::refine_method::rotations)); }},
        {"ch06-binned16-reinserted", "06", "chapter 05's binned SAH BVH (16 bins) refined by reinsertion (Bittner et al. 2013)",
         [] { return ch06::make_accel(false, refined(ch06::start_tree::binned16, ch06::refine_method::reinsertion)); }},
        {"ch06-binned16-reinserted-fast", "06", "the same reinserted tree, walked by chapter 05's faster scalar traversal",
         [] {
             return ch06::make_accel(false, refined(ch06::start_tree::binned16, ch06::refine_method::reinsertion),
                                     ch05::walk_kind::fast);
         }},
        lbvh("ch07-lbvh30-fast", "LBVH: 30-bit Morton codes, radix sort, the lecture's top-down split search, SAH "
             "collapse; chapter 05's fast walk", ch07::hierarchy_method::lecture, 10),
        lbvh("ch07-lbvh63-fast", "the same LBVH with 63-bit Morton codes", ch07::hierarchy_method::lecture, 21),
        lbvh("ch07-karras30-fast", "LBVH, 30-bit codes, Karras's parallel hierarchy (HPG 2012); chapter 05's fast walk",
             ch07::hierarchy_method::karras, 10),
        {"ch09-sbvh-fast", "09", "SBVH: chapter 05's binned SAH with spatial splits (Stich et al. 2009; alpha 1e-5, "
         "1.5 references per triangle at most); chapter 05's fast walk",
         [] { return std::unique_ptr<accel>(ch09::make_accel({}, "ch09-sbvh-fast")); }},
        {"ch09-sbvh-bvh8", "09", "chapter 09's SBVH collapsed into 8-wide nodes (optimal), blocks of 4; chapter 13's wide walk",
         [] { return std::unique_ptr<accel>(ch13::make_accel_from_mesh("ch09-sbvh-bvh8", [](const triangle_mesh& m) {
             return ch09::build_sbvh(m); }, wide_optimal(8, 4))); }},
        {"ch10-two-level", "10", "two-level BVH: chapter 05's binned SAH tree per mesh, one over the instances; the ray "
         "moved into each instance's object space (a plain scene is one instance)",
         [] { return std::unique_ptr<accel>(ch10::make_accel()); }, false, "ch10-brute-instanced"},
        ch11_step(ch11::step::virtual_calls), ch11_step(ch11::step::variant), ch11_step(ch11::step::type_sorted),
        ch11_step(ch11::step::triangles_only), ch11_step(ch11::step::inlined), ch11_step(ch11::step::soa),
        packets(ch12::walk_kind::masked, 16, 4, 4, o.packet_width), packets(ch12::walk_kind::ranged, 16, 8, 8, o.packet_width),
        packets(ch12::walk_kind::partition, 16, 16, 16, o.packet_width), packets(ch12::walk_kind::wide, 8, 4, 2, o.packet_width),
        packets(ch12::walk_kind::wide, 16, 4, 4, o.packet_width), packets(ch12::walk_kind::frustum, 16, 4, 4, o.packet_width),
        wide("ch13-bvh4", "chapter 05's binned SAH tree collapsed greedily into 4-wide nodes, leaves in blocks of 4 triangles",
             4, 4, ch13::collapse_method::greedy),
        wide("ch13-bvh8", "the same tree collapsed greedily into 8-wide nodes, blocks of 4", 8, 4, ch13::collapse_method::greedy),
        wide("ch13-bvh8-optimal", "the same tree collapsed into 8-wide nodes by the SAH-optimal dynamic program, blocks of 4",
             8, 4, ch13::collapse_method::optimal),
        wide("ch13-bvh8-block8", "8-wide nodes (optimal collapse), leaves in blocks of 8 triangles", 8, 8,
             ch13::collapse_method::optimal),
        wide("ch13-bvh8-block8-area", "8-wide nodes (optimal collapse), blocks of 8, children stored leaves first, then "
             "by decreasing surface area (the any-hit walk's order)", 8, 8, ch13::collapse_method::optimal, false, false,
             ch13::child_order::leaves_then_area),
        wide("ch13-bvh8-block8-octant", "as ch13-bvh8-block8, closest hit visiting the children in each node's order for "
             "the ray's octant (by their centres along the octant's diagonal, found at build) instead of sorting "
             "them by entry distance", 8, 8, ch13::collapse_method::optimal, false, false,
             ch13::child_order::collapsed, false, true),
        wide("ch13-bvh8-block8-quant", "as ch13-bvh8-block8, its nodes quantised: child boxes as bytes on a "
             "power-of-two grid per node, rounded outward (128-byte nodes instead of 256)", 8, 8,
             ch13::collapse_method::optimal, false, false, ch13::child_order::collapsed, true),
        wide("ch13-bvh16", "16-wide nodes (optimal collapse), blocks of 4", 16, 4, ch13::collapse_method::optimal),
        wide("ch13-bvh8-reinserted", "chapter 06's reinserted tree collapsed into 8-wide nodes (optimal), blocks of 4",
             8, 4, ch13::collapse_method::optimal, true),
        hybrid(8, ch14::automatic, o.packet_width), hybrid(16, ch14::automatic, o.packet_width),
        hybrid(16, ch14::automatic, o.packet_width, true), final_tracer(o.packet_width), final_tracer(o.packet_width, true),
        {"ch15-mt-fast", "15", "chapter 05's binned SAH tree and fast walk, Moeller-Trumbore: chapter 15's baseline",
         [] { return ch15::make_tree(ch15::test_kind::mt, ch15::box_kind::fast); }},
        {"ch15-watertight-fast", "15", "the same tree and walk with the watertight test (Woop, Benthin and Wald 2013)",
         [] { return ch15::make_tree(ch15::test_kind::watertight, ch15::box_kind::fast); }, false, "brute-watertight"},
        [] {
            accel_entry e = wide("ch15-watertight-bvh16", "chapter 13's 16-wide BVH (optimal collapse, blocks of 4) with "
                                 "the watertight test on 4 lanes", 16, 4, ch13::collapse_method::optimal, false, true);
            e.chapter = "15";
            e.oracle = "brute-watertight";
            return e;
        }(),
        {"brute-watertight", "15", "brute force with the watertight test: the oracle of chapter 15's watertight rows",
         [] { return ch15::make_brute(ch15::test_kind::watertight); }, true, "brute-watertight"},
        // Later chapters register here, one line each.
    };
    // Chapter 08, its builders in variants()' order, after chapter 07's (the table keeps chapter order).
    const auto after07 = std::find_if(list.rbegin(), list.rend(), [](const accel_entry& e) { return e.chapter == "07"; }).base();
    std::vector<accel_entry> ch08_entries;
    for (const ch08::variant& v : ch08::variants())
        ch08_entries.push_back({"ch08-" + v.name + "-fast", "08", v.description + "; chapter 05's fast walk",
                                [v] { return std::unique_ptr<accel>(ch08::make_accel(v)); }});
    list.insert(after07, ch08_entries.begin(), ch08_entries.end());
    if (embree_available()) {
        using q = embree_config::quality;
        list.push_back({"embree-low", "--", "Embree 3, low build quality (its Morton-code build), rtcIntersect1/rtcOccluded1",
                        [o] { return make_embree_accel({q::low, 0, o.threads}); }});
        list.push_back({"embree-medium", "--", "Embree 3, medium build quality, rtcIntersect1/rtcOccluded1",
                        [o] { return make_embree_accel({q::medium, 0, o.threads}); }});
        list.push_back({"embree-high", "--", "Embree 3, high build quality (spatial splits), rtcIntersect1/rtcOccluded1",
                        [o] { return make_embree_accel({q::high, 0, o.threads}); }});
        list.push_back({"embree-medium-instanced", "--", "Embree 3, medium quality, its own instancing: a scene per mesh, "
                        "an instance geometry per instance (chapter 10's yardstick; a plain scene is one instance)",
                        [o] {
                            embree_config c{q::medium, 0, o.threads};
                            c.instanced = true;
                            return make_embree_accel(c);
                        }, false, "ch10-brute-instanced"});
        // Embree's packet and stream calls, on tiles of rows of the race's image width (both queries, every
        // ray set: secondary rays are in the order of their pixels).
        using calls = embree_config::calls;
        const auto tiled = [o](calls c, bool coherent) {
            return [o, c, coherent] {
                embree_config config{q::medium, o.packet_width, o.threads};
                config.queries = c, config.coherent = coherent;
                return make_embree_accel(config);
            };
        };
        if (o.packet_width > 0) {
            list.push_back({"embree-medium-packet8", "--", "Embree 3, medium quality, rtcIntersect8/rtcOccluded8 on 4x2 ray tiles",
                            tiled(calls::packet8, false)});
            list.push_back({"embree-medium-packet8-coherent", "--", "the same packets with Embree's coherent flag "
                            "(RTC_INTERSECT_CONTEXT_FLAG_COHERENT)", tiled(calls::packet8, true)});
            list.push_back({"embree-medium-packet16-coherent", "--", "Embree 3, medium quality, rtcIntersect16/rtcOccluded16 "
                            "on 4x4 ray tiles, coherent flag", tiled(calls::packet16, true)});
            list.push_back({"embree-medium-stream-coherent", "--", "Embree 3, medium quality, ray streams: "
                            "rtcIntersect1M/rtcOccluded1M on the 64 rays of 8x8 tiles, coherent flag",
                            tiled(calls::stream, true)});
        }
    }
    return list;
}

// ch15-TEST-BOX and brute-TEST (registry.hpp); else nothing.
std::optional<accel_entry> ch15_by_name(const std::string& name) {
    for (const ch15::test_kind k : ch15::all_tests) {
        const std::string test = ch15::name(k);
        // Exercise 01.3's test and 11.2's form of it give brute force's answers bit for bit.
        const bool same_as_brute = k == ch15::test_kind::mt || k == ch15::test_kind::mt_edges;
        const std::string oracle = same_as_brute ? "brute" : "brute-" + test;
        if (name == "brute-" + test)
            return accel_entry{name, "15", std::string("brute force with chapter 15's test: ") + ch15::describe(k),
                               [k] { return ch15::make_brute(k); }, true, "brute-" + test};
        for (const ch15::box_kind b : ch15::all_boxes)
            if (name == "ch15-" + test + "-" + ch15::name(b))
                return accel_entry{name, "15", std::string("chapter 05's tree, ") + ch15::describe(k) + ", box test " +
                                                   ch15::name(b),
                                   [k, b] { return ch15::make_tree(k, b); }, false, oracle};
    }
    return std::nullopt;
}

// ch05-binnedK or ch05-binnedK-fast for K in [2, 256], written without sign or leading zeros; else nothing.
std::optional<accel_entry> binned_by_name(const std::string& name) {
    const std::string prefix = "ch05-binned";
    if (name.rfind(prefix, 0) != 0) return std::nullopt;
    std::string digits = name.substr(prefix.size());
    const bool fast = digits.size() > 5 && digits.ends_with("-fast");
    if (fast) digits.resize(digits.size() - 5);
    if (digits.empty() || digits.size() > 3 || digits[0] == '0' ||
        digits.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
    const int k = std::stoi(digits);
    if (k < 2 || k > 256) return std::nullopt;
    const ch05::sah_build_params p = sah(ch05::sah_method::binned, k);
    if (fast)
        return accel_entry{name, "05", "chapter 05's fast binned SAH build with " + digits + " bins, its faster traversal",
                           [p] { return ch05::make_accel(false, p, ch05::walk_kind::fast); }};
    return accel_entry{name, "05", "BVH, binned SAH with " + digits + " bins per axis, chapter 04's traversal",
                       [p] { return ch05::make_accel(false, p); }};
}

// ch12-WALKK-WxH for chapter 12's other built combinations (ch12::make_accel); else nothing.
std::optional<accel_entry> ch12_by_name(const std::string& name, const registry_options& o) {
    using w = ch12::walk_kind;
    for (const w walk : {w::masked, w::ranged, w::partition, w::wide, w::frustum})
        for (const auto& [lanes, tw, th] : {std::tuple{4, 2, 2}, {8, 4, 2}, {16, 4, 4}, {16, 8, 8}, {16, 16, 16}}) {
            accel_entry e = packets(walk, lanes, tw, th, o.packet_width);
            if (e.name != name) continue;
            ch12::make_accel(name, {walk, lanes, tw, th, 0});  // throws, naming what is built, for another
            return e;
        }
    return std::nullopt;
}

// ch14-hybridK-T[-strict][-stored] for K = 8 or 16 and T = 0..K or auto; else nothing.
std::optional<accel_entry> ch14_by_name(const std::string& name, const registry_options& o) {
    for (const int lanes : {8, 16})
        for (int t = ch14::automatic; t <= lanes; ++t)
            for (const bool strict : {false, true})
                for (const bool stored : {false, true}) {
                    accel_entry e = hybrid(lanes, t, o.packet_width, strict, stored);
                    if (e.name == name) return e;
                }
    return std::nullopt;
}

accel_entry find_accel(const std::string& name, const registry_options& options) {
    std::string names;
    for (accel_entry& e : registered_accels(options)) {
        if (e.name == name) return e;
        names += (names.empty() ? "" : ", ") + e.name;
    }
    if (std::optional<accel_entry> e = binned_by_name(name)) return *e;
    if (std::optional<accel_entry> e = ch15_by_name(name)) return *e;
    if (std::optional<accel_entry> e = ch12_by_name(name, options)) return *e;
    if (std::optional<accel_entry> e = ch14_by_name(name, options)) return *e;
    if (name == "ch10-brute-instanced")
        return accel_entry{name, "10", "chapter 10's instanced brute force: every instance, the ray in its object space",
                           [] { return ch10::make_brute_accel(); }, true, name};
    throw std::invalid_argument("no structure named '" + name + "' (have: " + names +
                                "; and ch10-brute-instanced; ch12-WALKK-WxH for chapter 12's packets (masked4-2x2, masked8-4x2, "
                                "ranged16-16x16, partition16-8x8, wide16-... as built); ch14-hybridK-T[-strict][-stored] for chapter 14's hybrid (K 8 or "
                                "16, T 0..K or auto; -strict: boxes from tmin, not exact; -stored: any hit in stored order); ch05-binnedK, ch05-binnedK-fast for K in 2..256; ch15-TEST-BOX and brute-TEST "
                                "for chapter 15's tests mt, mt-epsilon, mt-edges, watertight, watertight-double and "
                                "boxes plain, conservative, fast)");
}

}  // namespace strahl::race
