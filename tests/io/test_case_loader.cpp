#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "dem/io/case_loader.h"
#include "io_test_support.h"

namespace dem::io {
namespace {

using ::testing::HasSubstr;

std::string load_error(const std::filesystem::path& path) {
  try {
    load_case_file(path);
  } catch (const CaseError& error) {
    return error.what();
  }
  ADD_FAILURE() << path << " loaded without an error";
  return {};
}

std::string text_error(const std::string& text) {
  try {
    parse_case_text(text, "case.txtpb");
  } catch (const CaseError& error) {
    return error.what();
  }
  ADD_FAILURE() << "parsed without an error:\n" << text;
  return {};
}

TEST(CaseLoader, LoadsAFile) {
  const LoadedCase loaded = load_case_file(test::data_path("valid.case.txtpb"));
  EXPECT_EQ(loaded.message.name(), "nine_discs");
  EXPECT_EQ(loaded.message.particles_size(), 3);
  EXPECT_EQ(loaded.message.wall_size(), 4);
  EXPECT_EQ(loaded.source.name, test::data_path("valid.case.txtpb").string());
  EXPECT_NE(loaded.source.locations, nullptr);
}

TEST(CaseLoader, SyntaxErrorNamesFileLineAndColumnAndShowsTheLine) {
  const std::string message = load_error(test::data_path("syntax_error.case.txtpb"));
  // The line starts with a tab, which the parser counts to column 8.
  EXPECT_THAT(message, HasSubstr("syntax_error.case.txtpb:7:18: Expected integer, got: -"));
  EXPECT_THAT(message, HasSubstr("  7 |         columns: -3\n    |                  ^"));
}

TEST(CaseLoader, UnknownFieldIsNamedWithItsLine) {
  const std::string message = load_error(test::data_path("unknown_field.case.txtpb"));
  EXPECT_THAT(message, HasSubstr("unknown_field.case.txtpb:4:"));
  EXPECT_THAT(message, HasSubstr("no field named \"wal\""));
}

TEST(CaseLoader, TextErrorsUseTheGivenSourceName) {
  EXPECT_THAT(text_error("name: \"a\"\nmaterial { density: \"heavy\" }\n"),
              HasSubstr("case.txtpb:2:21: Expected double, got: \"heavy\""));
  EXPECT_THAT(text_error("wall { name: \"top\" \n"),
              HasSubstr("case.txtpb:2:1: Expected identifier, got: end of file"));
  EXPECT_THAT(text_error("name: \"a\"\nname: \"b\"\n"),
              HasSubstr("case.txtpb:2:5: Non-repeated field \"name\" is specified multiple times."));
}

TEST(CaseLoader, AHertzLawTakesOneKindOfDamping) {
  EXPECT_THAT(text_error("contact_model {\n  hertz_mindlin { damping_ratio: 0.1 restitution: 0.5 }\n}\n"),
              HasSubstr("case.txtpb:2:49: Field \"restitution\" is specified along with field \"damping_ratio\", "
                        "another member of oneof \"damping\""));
}

TEST(CaseLoader, AContactModelTakesOneLaw) {
  EXPECT_THAT(text_error("contact_model {\n  linear { normal_stiffness: 1 }\n  hertz_mindlin {}\n}\n"),
              HasSubstr("case.txtpb:3:17: Field \"hertz_mindlin\" is specified along with field \"linear\""));
}

TEST(CaseLoader, RelativeFilesAreFoundBesideTheCase) {
  EXPECT_EQ(load_case_file(test::data_path("valid_3d.case.txtpb")).source.directory,
            test::data_path("valid_3d.case.txtpb").parent_path());
  EXPECT_EQ(parse_case_text("").source.directory, std::filesystem::path());
}

TEST(CaseLoader, MissingFileIsNamed) {
  const auto path = test::data_path("no_such.case.txtpb");
  EXPECT_THAT(load_error(path), HasSubstr(path.string() + ": cannot read the case file: No such file or directory"));
}

TEST(CaseLoader, DirectoryIsNamed) {
  EXPECT_THAT(load_error(test::data_path("")), HasSubstr("cannot read the case file: it is a directory"));
}

TEST(CaseLoader, EmptyTextIsAnEmptyCase) {
  // Parsing accepts it; validation is what reports the missing parts.
  EXPECT_EQ(parse_case_text("").message.ByteSizeLong(), 0u);
}

TEST(CaseLoader, BinaryRoundTrip) {
  const proto::Case original = test::valid_case();
  const LoadedCase loaded = parse_case_binary(original.SerializeAsString(), "request 7");
  EXPECT_EQ(loaded.message.SerializeAsString(), original.SerializeAsString());
  EXPECT_EQ(loaded.source.name, "request 7");
  EXPECT_EQ(loaded.source.locations, nullptr);
}

TEST(CaseLoader, BinaryGarbageIsRejected) {
  try {
    parse_case_binary(std::string("\xff\xff\xff\xff", 4), "request 8");
    FAIL() << "garbage parsed";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("request 8: not a serialized dem.proto.Case message"));
  }
}

}  // namespace
}  // namespace dem::io
