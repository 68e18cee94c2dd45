// Test helper: EXPECT_HAS(text, "part", ...) expects every part to occur in the text (an error
// message naming its file, line and key, say), printing the whole text when one is missing.
#pragma once

#include <gtest/gtest.h>

#include <string>

#define EXPECT_HAS(text, ...)                                                                 \
  do {                                                                                        \
    const std::string t_ = (text);                                                            \
    for (const char* part : {__VA_ARGS__}) EXPECT_NE(t_.find(part), std::string::npos) << t_; \
  } while (0)
