// The script language's table: its rows are well formed, docs/modeler.md describes each, `help`
// lists them, and a line runs the row its first word names (the session's before the
// application's).
#include "stitch/modeler/script_commands.hpp"

#include <gtest/gtest.h>

#include <set>

#include "docs_text.hpp"
#include "printed_lines.hpp"
#include "stitch/modeler/session.hpp"
#include "stitch/output/output.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch::modeler {
namespace {

/// An application row as the modeler's window adds them (apps/modeler/commands.cpp).
ScriptHooks hooks_with_window_line(Printed& printed, int& runs) {
  ScriptHooks hooks = printed.hooks();
  hooks.commands.push_back({"window-only", "window-only on|off", "a line about the window",
                            [&runs](Session&, const ScriptLine& line, const ScriptHooks&) {
                              ++runs;
                              return ScriptResult{false, "window " + line.rest()};
                            }});
  return hooks;
}

TEST(ScriptCommands, RowsHaveUniqueNamesASynopsisAndHelp) {
  std::set<std::string_view> names;
  for (const ScriptCommand& c : script_command_table()) {
    SCOPED_TRACE(std::string(c.name));
    EXPECT_FALSE(c.name.empty());
    EXPECT_TRUE(names.insert(c.name).second);
    EXPECT_EQ(find_operation(c.name), nullptr);  // an operation would shadow the row
    EXPECT_TRUE(c.synopsis == c.name || c.synopsis.starts_with(std::string(c.name) + " "));
    EXPECT_FALSE(c.help.empty());
    EXPECT_EQ(c.help.find('\n'), std::string_view::npos);
    EXPECT_TRUE(c.run);
    EXPECT_EQ(find_script_command(script_command_table(), c.name), &c);
  }
  EXPECT_EQ(find_script_command(script_command_table(), "frobnicate"), nullptr);
  for (const char* alias : {"quit", "exit", "undo", "redo", "move-vertex", "translate-vertex"})
    EXPECT_TRUE(names.contains(alias)) << alias;
}

TEST(ScriptCommands, TheModelerPageDescribesEveryRow) {
  const std::string docs = read_docs("modeler.md");
  ASSERT_FALSE(docs.empty()) << "docs/modeler.md not found";
  for (const ScriptCommand& c : script_command_table())
    EXPECT_TRUE(names_in_code(docs, c.name)) << "docs/modeler.md does not name `" << c.name << "`";
}

TEST(ScriptCommands, LinesThatTakeANameReadTheLibrarysTables) {
  auto row = [](std::string_view name) {
    return *find_script_command(script_command_table(), name);
  };
  EXPECT_EQ(row("method").synopsis, "method " + choice_names(method_table(), "|"));
  // The modeler's own rows: "off" before the methods, "input" after the shading modes.
  EXPECT_EQ(row("split").synopsis, "split off|" + choice_names(method_table(), "|"));
  EXPECT_EQ(row("mode").synopsis, "mode " + choice_names(shading_mode_table(), "|") + "|input");
  EXPECT_NE(row("export").help.find(output_extensions()), std::string::npos) << row("export").help;

  Session s(make_cube());
  for (const Choice<Method>& m : method_table()) {
    ASSERT_FALSE(run_script(s, {"method " + std::string(m.name)}, {}));
    EXPECT_EQ(s.display.method, m.value);
    EXPECT_EQ(s.surface.method(), m.value);
  }
  for (const Choice<std::optional<Method>>& m : split_table()) {
    ASSERT_FALSE(run_script(s, {"split " + std::string(m.name)}, {}));
    EXPECT_EQ(s.display.split, m.value);
  }
  for (const Choice<DisplayMode>& m : display_mode_table()) {
    ASSERT_FALSE(run_script(s, {"mode " + std::string(m.name)}, {}));
    EXPECT_EQ(display_mode(s.display), m.value);
    EXPECT_EQ(s.display.input_polygons, !m.value);
  }
  EXPECT_EQ(row("up").synopsis, "up " + choice_names(up_axis_table(), "|"));
  for (const Choice<UpAxis>& u : up_axis_table()) {
    ASSERT_FALSE(run_script(s, {"up " + std::string(u.name)}, {}));
    EXPECT_EQ(s.view.up, u.value);
  }
  const auto error = run_script(s, {"mode frobnicate"}, {});
  ASSERT_TRUE(error);
  EXPECT_EQ(error->message, "unknown display mode 'frobnicate' (known: " +
                                choice_names(display_mode_table()) + ")");
  EXPECT_TRUE(run_script(s, {"split frobnicate"}, {}));
  // A new session's display: the tables' defaults.
  const DisplaySettings fresh;
  EXPECT_EQ(fresh.method, method_table().front().value);
  EXPECT_EQ(fresh.mode, shading_mode_table().front().value);
  EXPECT_EQ(fresh.resolution, kDefaultResolution);
}

TEST(ScriptCommands, LinesRunTheRowTheirFirstWordNames) {
  Session s(make_cube());
  ScriptLine line = read_script_line("  save my model.obj   # a comment");
  EXPECT_EQ(line.words, (std::vector<std::string>{"save", "my", "model.obj"}));
  EXPECT_EQ(line.rest(), "my model.obj");
  EXPECT_EQ(read_script_line("select corner 1@2#1").words.back(), "1@2#1");  // not a comment

  Printed printed;
  int runs = 0;
  const ScriptHooks hooks = hooks_with_window_line(printed, runs);
  EXPECT_EQ(run_script_line(s, "window-only on  # c", hooks).message, "window on");
  EXPECT_EQ(runs, 1);
  EXPECT_TRUE(run_script_line(s, "exit", hooks).quit);
  EXPECT_TRUE(run_script_line(s, "quit", hooks).quit);
  EXPECT_EQ(run_script_line(s, "# window-only off", hooks).message, "");
  EXPECT_EQ(runs, 1);

  // An unknown name: the message lists every table's names.
  try {
    run_script_line(s, "frobnicate 1", hooks);
    ADD_FAILURE() << "frobnicate ran";
  } catch (const UsageError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("unknown command 'frobnicate'"), std::string::npos) << m;
    EXPECT_NE(m.find("operations: " + operation_names()), std::string::npos) << m;
    EXPECT_NE(m.find("modeler: primitive, move-vertex,"), std::string::npos) << m;
    EXPECT_NE(m.find("unfold-tubes, quit, exit, help; application: window-only)"),
              std::string::npos)
        << m;
  }
}

TEST(ScriptCommands, HelpListsEveryTableThroughPrint) {
  Session s(make_cube());
  Printed printed;
  int runs = 0;
  const ScriptHooks hooks = hooks_with_window_line(printed, runs);
  const ScriptResult r = run_script_line(s, "help", hooks);
  EXPECT_FALSE(r.message.empty());
  std::string all;
  for (const std::string& l : printed.lines) all += l + "\n";
  auto listed = [&](std::string_view synopsis, std::string_view help) {
    const size_t at = all.find("  " + std::string(synopsis));
    return at != std::string::npos && all.find(help, at) != std::string::npos;
  };
  for (const OperationInfo& op : operation_table())
    EXPECT_TRUE(listed(op.synopsis, op.summary)) << op.name << "\n" << all;
  for (const ScriptCommand& c : script_command_table())
    EXPECT_TRUE(listed(c.synopsis, c.help)) << c.name << "\n" << all;
  EXPECT_TRUE(listed("window-only on|off", "a line about the window")) << all;
  EXPECT_LT(all.find("modeler:"), all.find("application:"));
  EXPECT_EQ(runs, 0);

  // One row by its name, in any table.
  printed.lines.clear();
  EXPECT_EQ(run_script_line(s, "help kgon", hooks).message.rfind("kgon [global] scale S", 0), 0u);
  EXPECT_EQ(run_script_line(s, "help window-only", hooks).message,
            "window-only on|off: a line about the window");
  EXPECT_EQ(run_script_line(s, "help insert-edge", hooks).message.rfind("insert-edge V@F V@F", 0),
            0u);
  EXPECT_EQ(printed.lines.size(), 3u);
  EXPECT_THROW(run_script_line(s, "help frobnicate", hooks), UsageError);
  EXPECT_THROW(run_script_line(s, "help kgon mode", hooks), UsageError);
}

}  // namespace
}  // namespace stitch::modeler
