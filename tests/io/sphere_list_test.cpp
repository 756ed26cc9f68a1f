#include "molmesh/io/sphere_list.hpp"

#include <gtest/gtest.h>

#include "io/io_test_support.hpp"
#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

using test::expect_input_error;
using test::write_text;

TEST(SphereList, ReadsCommentsBlankLinesAndCommas) {
  const auto spheres = read_spheres(write_text("s.txt",
                                               "# active site of mAChE (gorge)\n"
                                               "\n"
                                               "  1.5 -2.0 3.25 4.0   # Trp86\n"
                                               "10,20,30,0\n"
                                               "\t-1e1 0 0 2.5\r\n"));
  ASSERT_EQ(spheres.size(), 3u);
  EXPECT_EQ(spheres[0].center, Vec3(1.5, -2.0, 3.25));
  EXPECT_EQ(spheres[0].radius, 4.0);
  EXPECT_EQ(spheres[1].radius, 0.0);
  EXPECT_EQ(spheres[2].center.x(), -10.0);
  EXPECT_TRUE(spheres[0].contains(Vec3(1.5, -2.0, 7.0)));
}

TEST(SphereList, Errors) {
  expect_input_error([] { read_spheres(write_text("a.txt", "1 2 3 4\n1 2 3\n")); },
                     {"a.txt:2:", "found 3 fields"});
  expect_input_error([] { read_spheres(write_text("b.txt", "1 2 x 4\n")); }, {"b.txt:1:", "'x'"});
  expect_input_error([] { read_spheres(write_text("c.txt", "1 2 3 -4\n")); },
                     {"c.txt:1:", "negative"});
  expect_input_error([] { read_spheres(write_text("d.txt", "1 2 nan 4\n")); },
                     {"d.txt:1:", "finite"});
  expect_input_error([] { read_spheres(write_text("e.txt", "# none\n\n")); },
                     {"e.txt", "no spheres"});
  expect_input_error([] { read_spheres(testing::test_dir() / "f.txt"); },
                     {"f.txt", "no such file"});
}

}  // namespace
}  // namespace molmesh
