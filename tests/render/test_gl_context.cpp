// The OSMesa context: a core profile of at least OpenGL 3.3 when Mesa can give one, and a
// RenderError carrying OSMesa's reason when it cannot.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "render/gl_context.hpp"
#include "render/render_error.hpp"

namespace gearsim::render {
namespace test_gl_context {

TEST(GlContext, GivesACoreProfileOfAtLeast33) {
  GlContext context;
  int major = 0, minor = 0;
  ASSERT_EQ(std::sscanf(context.version().c_str(), "%d.%d", &major, &minor), 2) << context.version();
  EXPECT_GE(major * 10 + minor, 33) << context.version();
  EXPECT_NE(context.version().find("Core Profile"), std::string::npos) << context.version();
  EXPECT_GE(context.max_size_px(), 4096);
}

// Mesa reads MESA_GL_VERSION_OVERRIDE once per process, so the refusal runs in a fresh child
// ("threadsafe" death tests re-execute the binary). Exit code 3 = RenderError naming the profile
// and what OSMesa offers instead.
TEST(GlContextDeathTest, RefusalIsARenderErrorWithOsMesasReason) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("MESA_GL_VERSION_OVERRIDE", "3.1", 1);
        try {
          GlContext context;
        } catch (const RenderError& e) {
          const bool named = std::strstr(e.what(), "core-profile") && std::strstr(e.what(), "3.1");
          std::exit(named ? 3 : 4);
        }
        std::exit(5);
      },
      ::testing::ExitedWithCode(3), "");
}

}  // namespace test_gl_context
}  // namespace gearsim::render
