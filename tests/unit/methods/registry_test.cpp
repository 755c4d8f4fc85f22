// SPDX-License-Identifier: MIT
#include "dtm/methods/registry.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm::methods {
namespace {

TEST(MethodsRegistry, NamesAreUniqueAndFindable) {
    std::set<std::string> names;
    for (const MethodInfo& m : registry()) {
        EXPECT_TRUE(names.insert(std::string(m.name)).second) << m.name;
        EXPECT_EQ(find_method(m.name), &m);
        EXPECT_NE(m.run, nullptr) << m.name;
        EXPECT_FALSE(m.source.empty()) << m.name;
        EXPECT_FALSE(m.complexity.empty()) << m.name;
        EXPECT_NE(family_name(m.family), "?");
    }
    EXPECT_EQ(find_method("no-such-method"), nullptr);
    ASSERT_NE(find_method("dc"), nullptr);
}

TEST(MethodsRegistry, ReferenceKernelGivesAValidDelaunayTin) {
    const auto points = test::random_points(2000, 7);
    const MethodInfo* dc = find_method("dc");
    ASSERT_NE(dc, nullptr);
    const MethodResult result = dc->run(MethodInput{points, {}}, MethodOptions{}, Progress{});
    EXPECT_TRUE(verify_topology(result.tin).ok());
    EXPECT_TRUE(verify_constrained_delaunay(result.tin).ok());
    EXPECT_EQ(result.tin.vertices.size(), points.size());
}

TEST(MethodsRegistry, ReferenceKernelRejectsUnknownParameters) {
    const auto points = test::random_points(10, 1);
    MethodOptions options;
    options.params["nonsense"] = "1";
    EXPECT_THROW((void)find_method("dc")->run(MethodInput{points, {}}, options, Progress{}),
                 UsageError);
}

}  // namespace
}  // namespace dtm::methods
