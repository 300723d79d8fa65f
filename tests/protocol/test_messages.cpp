// The messages generated from the IDL (dem/protocol/messages.h): every
// member of every message, filled with a value of its own, goes C++ ->
// idlc's C struct -> CDR (as Cyclone serializes a sample) -> C -> C++ and
// comes back equal, member by member. A member that a conversion leaves out
// comes back as its default and fails here, by name.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <type_traits>

#include "dem/protocol/command_cdr.h"
#include "dem/protocol/messages.h"

namespace dem::protocol {
namespace {

template <class T>
struct IsVector : std::false_type {};
template <class T>
struct IsVector<std::vector<T>> : std::true_type {};
template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

// Gives each member a value no other member has and none is a default.
class Filler {
 public:
  template <class T>
  void fill(T& value) {
    const int n = ++count_;
    if constexpr (Message<T>) {
      std::apply([&](const auto&... field) { (fill(value.*field.member), ...); }, Fields<T>::list);
    } else if constexpr (IsVector<T>::value) {
      value.resize(2);
      for (auto& element : value) fill(element);
    } else if constexpr (IsOptional<T>::value) {
      fill(value.emplace());
    } else if constexpr (std::is_same_v<T, std::string>) {
      value = "member " + std::to_string(n);
    } else if constexpr (std::is_same_v<T, bool>) {
      value = true;
    } else if constexpr (std::is_enum_v<T>) {
      value = static_cast<T>(1 + n % 3);  // 1..3: a constant of every enum
    } else if constexpr (std::is_integral_v<T> && sizeof(T) == 1) {
      value = static_cast<T>(1 + n % 100);
    } else {
      value = static_cast<T>(n) + static_cast<T>(1) / static_cast<T>(4);  // n.25 for floating point
    }
  }

 private:
  int count_ = 0;
};

// Compares member by member, naming the path of each that differs.
template <class T>
void expect_same(const T& got, const T& wanted, const std::string& path) {
  if constexpr (Message<T>) {
    std::apply(
        [&](const auto&... field) {
          (expect_same(got.*field.member, wanted.*field.member, path + "." + std::string(field.name)), ...);
        },
        Fields<T>::list);
  } else if constexpr (IsVector<T>::value) {
    ASSERT_EQ(got.size(), wanted.size()) << path;
    for (std::size_t i = 0; i < got.size(); ++i) expect_same(got[i], wanted[i], path + "[" + std::to_string(i) + "]");
  } else {
    EXPECT_TRUE(got == wanted) << path << " came back different";
  }
}

template <class T>
class EveryMessage : public ::testing::Test {};

template <class Tuple>
struct AsTypes;
template <class... T>
struct AsTypes<std::tuple<T...>> {
  using type = ::testing::Types<T...>;
};
TYPED_TEST_SUITE(EveryMessage, AsTypes<Messages>::type);

TYPED_TEST(EveryMessage, EveryMemberComesBackThroughCAndCdr) {
  TypeParam message;
  Filler().fill(message);
  ASSERT_FALSE(message == TypeParam{});
  const std::optional<TypeParam> decoded = decode_cdr<TypeParam>(encode_cdr(message));
  ASSERT_TRUE(decoded);
  expect_same(*decoded, message, ::testing::internal::GetTypeName<TypeParam>());
  EXPECT_TRUE(*decoded == message);
}

// The check above can fail: every member counts in a message's equality
// (a member that the filler missed, or that == ignored, would pass unseen).
TYPED_TEST(EveryMessage, EveryMemberCountsInEquality) {
  TypeParam message;
  Filler().fill(message);
  std::apply(
      [&](const auto&... field) {
        (([&] {
           TypeParam changed = message;
           changed.*field.member = {};
           EXPECT_FALSE(changed == message) << field.name;
         }()),
         ...);
      },
      Fields<TypeParam>::list);
}

TEST(Messages, StatusCarriesItsStateByName) {
  Status status;
  status.state = ServerState::kRunning;
  EXPECT_NE(encode_cdr(status).find("running"), std::string::npos);
}

TEST(Messages, AStateOffTheWireThatIsNoneOfTheConstantsIsAnError) {
  Status status;
  status.state = static_cast<ServerState>(200);
  EXPECT_EQ(decode_cdr<Status>(encode_cdr(status))->state, ServerState::kError);
  EXPECT_EQ(to_string(static_cast<ServerState>(200)), "error");
  EXPECT_EQ(to_string(static_cast<CommandKind>(200)), "unknown");
  EXPECT_FALSE(command_kind(0));
  EXPECT_EQ(command_kind(13), CommandKind::kRunProgramme);
}

TEST(Messages, UnsetOptionalsTravelAsUnset) {
  RunUntilArgs until;
  until.stress = 1e5;
  const auto decoded = decode_cdr<RunUntilArgs>(encode_cdr(until));
  ASSERT_TRUE(decoded);
  EXPECT_EQ(decoded->stress, 1e5);
  EXPECT_FALSE(decoded->settlement);
  EXPECT_FALSE(decoded->kinetic_energy);
}

}  // namespace
}  // namespace dem::protocol
