// The viewer's keys (view/ViewKeys.hpp): window codes and --keys names to keys, and the help.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "zrender/base/Error.hpp"
#include "zrender/view/ViewKeys.hpp"

namespace zrender {
namespace {

TEST(ViewKeys, WindowCodesFindTheirKeysLettersInEitherCase) {
  EXPECT_EQ(viewKeyForCode(' ').value().action, ViewAction::NextAlgorithm);
  EXPECT_EQ(viewKeyForCode('w').value().action, ViewAction::TiltUp);
  EXPECT_EQ(viewKeyForCode('W').value().action, ViewAction::TiltUp);
  EXPECT_EQ(viewKeyForCode('3').value().rank, 2);
  EXPECT_EQ(viewKeyForCode('=').value().action, ViewAction::Closer);
  EXPECT_EQ(viewKeyForCode(13).value().action, ViewAction::SaveFrame);
  EXPECT_EQ(viewKeyForCode(27).value().action, ViewAction::Quit);
  EXPECT_FALSE(viewKeyForCode('x'));
  EXPECT_FALSE(viewKeyForCode(-1));
  EXPECT_FALSE(viewKeyForCode(65505));  // shift, as X reports it
}

TEST(ViewKeys, ListsOfNamesParseInOrder) {
  const auto keys = parseViewKeys("space,space,W,s,m,t,plus,minus,-,enter,esc,5", "--keys");
  ASSERT_EQ(keys.size(), 12u);
  EXPECT_EQ(keys[0].code, ' ');
  EXPECT_EQ(keys[1].code, ' ');
  EXPECT_EQ(keys[2].code, 'w');
  EXPECT_EQ(keys[3].code, 's');
  EXPECT_EQ(keys[6].code, '+');
  EXPECT_EQ(keys[7].code, '-');
  EXPECT_EQ(keys[8].code, '-');
  EXPECT_EQ(keys[9].code, 13);
  EXPECT_EQ(keys[10].code, 27);
  EXPECT_EQ(keys[11].action, ViewAction::PickAlgorithm);
  EXPECT_EQ(keys[11].rank, 4);
}

TEST(ViewKeys, AnUnknownNameIsAnErrorNamingTheOptionAndTheName) {
  for (const std::string list : {"space,jump,q", "", "w,,s", "x"}) {
    try {
      parseViewKeys(list, "--keys");
      ADD_FAILURE() << "'" << list << "' accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("command line: --keys: unknown key"), std::string::npos) << what;
      EXPECT_NE(what.find("space"), std::string::npos) << what;  // the list of names
    }
  }
  try {
    parseViewKeys("space,jump,q", "--keys");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'jump'"), std::string::npos) << e.what();
  }
}

TEST(ViewKeys, TheHelpListsEveryKeyOnce) {
  const std::string help = viewKeysHelp();
  for (const char* line : {"  space       next algorithm\n", "  1 2 3 4 5   ",
                           "  + =         ", "  q esc       quit\n", "  enter       save"})
    EXPECT_NE(help.find(line), std::string::npos) << line << " in\n" << help;
  EXPECT_EQ(std::count(help.begin(), help.end(), '\n'), 14);
}

}  // namespace
}  // namespace zrender
