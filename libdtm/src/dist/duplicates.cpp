// SPDX-License-Identifier: MIT
//
// Exact duplicates across ranks, with the serial merge's rules (algo/detail/input_merge.cpp):
//   1. every input point goes to rank hash(x, y) mod P with its global input index: all points
//      of one position meet on one rank;
//   2. there each group is ordered by input index; the first is kept, the heights fold in input
//      order (duplicate_rule_z), and every member's owner learns its representative and the
//      kept value;
//   3. owners number their kept vertices (exclusive scan of the counts, input order);
//   4. the numbers of kept vertices with duplicates go back to the group's rank, which forwards
//      them to the owners of the other members.
// Four alltoallv and two scans; no step depends on the rank count except where data travels.
//
// Reference: the hash partitioning of distributed duplicate elimination, e.g. P. Sanders et
// al., "Sequential and Parallel Algorithms and Data Structures", Springer 2019, ch. 4.
#include "dtm/dist/duplicates.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <unordered_map>

#include "algo/detail/input_merge.hpp"

namespace dtm::dist {
namespace {

/// The top bit of a record's index: the input's z is known.
constexpr std::uint64_t z_known_bit = std::uint64_t{1} << 63;

struct Record {  ///< an input point on its way to its group's rank (32 bytes)
    double x, y, z;
    std::uint64_t tagged;  ///< input index | z_known_bit
    [[nodiscard]] std::uint64_t index() const noexcept { return tagged & ~z_known_bit; }
    [[nodiscard]] bool z_known() const noexcept { return (tagged & z_known_bit) != 0; }
};

/// The second top bit of an answer's representative: the group has more than one member.
constexpr std::uint64_t duplicates_bit = std::uint64_t{1} << 62;

struct Answer {  ///< a group's answer to the owner of one member (24 bytes)
    std::uint64_t index;
    /// Input index of the kept point (index itself when kept) | z_known_bit | duplicates_bit.
    std::uint64_t tagged;
    double z;  ///< the kept vertex's final z
    [[nodiscard]] std::uint64_t representative() const noexcept {
        return tagged & ~(z_known_bit | duplicates_bit);
    }
    [[nodiscard]] bool z_known() const noexcept { return (tagged & z_known_bit) != 0; }
    [[nodiscard]] bool has_duplicates() const noexcept { return (tagged & duplicates_bit) != 0; }
};

struct Number {  ///< a kept vertex's number and position for a member input
    std::uint64_t index;
    std::uint64_t vertex;
    double x, y;  ///< the kept point's position
};

std::uint64_t position_hash(double x, double y) noexcept {
    // -0.0 and 0.0 are the same position.
    const std::uint64_t a = std::bit_cast<std::uint64_t>(x == 0.0 ? 0.0 : x);
    const std::uint64_t b = std::bit_cast<std::uint64_t>(y == 0.0 ? 0.0 : y);
    std::uint64_t h = a * 0x9E3779B97F4A7C15ULL ^ (b + 0x632BE59BD9B4E019ULL + (a << 6) + (a >> 2));
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ULL;
    return h ^ (h >> 29);
}

bool same_position(const Record& a, const Record& b) noexcept { return a.x == b.x && a.y == b.y; }

/// The rank holding input @p index, from every rank's first input (ascending).
std::uint32_t origin_of(const std::vector<std::uint64_t>& firsts, std::uint64_t index) {
    return static_cast<std::uint32_t>(std::upper_bound(firsts.begin(), firsts.end(), index) -
                                      firsts.begin() - 1);
}

}  // namespace

MergedShare merge_exact_duplicates(Comm& comm,
                                   std::span<const InputPoint> local,
                                   DuplicateRule rule) {
    comm.set_phase("duplicates");
    const auto ranks = static_cast<std::size_t>(comm.size());
    MergedShare share;
    share.first_input =
        static_cast<std::uint64_t>(comm.exscan_sum(static_cast<std::int64_t>(local.size())));
    share.total_inputs = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(local.size()), Reduce::sum));

    // 1. To the groups' ranks.
    std::vector<Bytes> out(ranks);
    for (std::size_t i = 0; i < local.size(); ++i) {
        const Point3& p = local[i].p;
        append_value(
            out[position_hash(p.x, p.y) % ranks],
            Record{p.x, p.y, p.z, (share.first_input + i) | (local[i].z_known ? z_known_bit : 0)});
    }
    std::vector<Record> records = concatenated<Record>(comm.alltoallv(std::move(out)));

    // 2. Groups ordered by position, then input index; the first of each is kept.
    std::sort(records.begin(), records.end(), [](const Record& a, const Record& b) {
        if (a.x != b.x) return a.x < b.x;
        if (a.y != b.y) return a.y < b.y;
        return a.index() < b.index();
    });
    Bytes first_bytes;
    append_value(first_bytes, share.first_input);
    const std::vector<std::uint64_t> firsts =
        concatenated<std::uint64_t>(comm.allgatherv(std::move(first_bytes)));
    out.assign(ranks, {});
    // Kept input -> its other members in `members` (index, origin): all step 4 needs of the
    // records, which are freed before the answers travel.
    std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t>> groups;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> members;
    for (std::size_t a = 0; a < records.size();) {
        std::size_t b = a + 1;
        while (b < records.size() && same_position(records[a], records[b])) ++b;
        double z = records[a].z;
        bool known = records[a].z_known();
        std::size_t count = known ? 1 : 0;
        for (std::size_t k = a + 1; k < b; ++k) {
            if (!records[k].z_known()) continue;
            ++count;
            z = known ? detail::duplicate_rule_z(rule, z, records[k].z, count) : records[k].z;
            known = true;
        }
        const bool has_duplicates = b - a > 1;
        const std::uint64_t tagged =
            records[a].index() | (known ? z_known_bit : 0) | (has_duplicates ? duplicates_bit : 0);
        if (has_duplicates) {
            groups.emplace(records[a].index(),
                           std::pair{members.size(), members.size() + b - a - 1});
            for (std::size_t k = a + 1; k < b; ++k)
                members.emplace_back(records[k].index(), origin_of(firsts, records[k].index()));
        }
        for (std::size_t k = a; k < b; ++k) {
            append_value(out[origin_of(firsts, records[k].index())],
                         Answer{records[k].index(), tagged, z});
        }
        a = b;
    }
    std::vector<Record>().swap(records);
    std::vector<Answer> answers = concatenated<Answer>(comm.alltoallv(std::move(out)));
    std::sort(answers.begin(), answers.end(),
              [](const Answer& a, const Answer& b) { return a.index < b.index; });

    // 3. Kept vertices numbered in input order.
    std::uint64_t kept = 0;
    for (const Answer& a : answers) kept += a.representative() == a.index ? 1 : 0;
    share.first_vertex =
        static_cast<std::uint64_t>(comm.exscan_sum(static_cast<std::int64_t>(kept)));
    share.total_vertices =
        static_cast<std::uint64_t>(comm.allreduce(static_cast<std::int64_t>(kept), Reduce::sum));
    share.vertex_of_input.assign(local.size(), 0);
    share.vertices.reserve(kept);  // no growth: the merge's peak is this step
    out.assign(ranks, {});
    for (std::size_t i = 0; i < local.size(); ++i) {
        const Answer& a = answers[i];
        if (a.representative() != a.index) continue;
        const std::uint64_t id = share.first_vertex + share.vertices.size();
        share.vertex_of_input[i] = id;
        share.vertices.push_back(
            {{local[i].p.x, local[i].p.y, a.z}, id & vertex_id_bits, a.z_known()});
        if (a.has_duplicates()) {
            append_value(out[position_hash(local[i].p.x, local[i].p.y) % ranks],
                         Number{a.index, id, local[i].p.x, local[i].p.y});
        }
    }

    // 4. The kept numbers to the other members' owners, through the groups' ranks.
    const std::vector<Number> kept_numbers = concatenated<Number>(comm.alltoallv(std::move(out)));
    out.assign(ranks, {});
    for (const Number& n : kept_numbers) {
        const auto [a, b] = groups.at(n.index);
        for (std::size_t k = a; k < b; ++k) {
            append_value(out[members[k].second], Number{members[k].first, n.vertex, n.x, n.y});
        }
    }
    std::vector<Number> numbers = concatenated<Number>(comm.alltoallv(std::move(out)));
    std::sort(numbers.begin(), numbers.end(),
              [](const Number& a, const Number& b) { return a.index < b.index; });
    for (const Number& n : numbers) {
        const std::size_t i = n.index - share.first_input;
        const Answer& a = answers[i];
        share.vertex_of_input[i] = n.vertex;
        const Point3& given = local[i].p;
        share.merges.push_back({a.representative(), a.index, {n.x, n.y, a.z}, given});
    }
    return share;
}

void MergedShare::keep_heights() {
    heights.reserve(heights.size() + vertices.size());
    for (const Vertex& v : vertices) heights.push_back(v.p.z);
    std::vector<Vertex>().swap(vertices);
}

}  // namespace dtm::dist
