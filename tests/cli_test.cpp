// The command line's own contract: version, usage errors.
#include <gtest/gtest.h>

#include <fstream>

#include "run_command.h"
#include "temp_folder.h"

namespace lancer::test {

TEST(Cli, PrintsVersion) {
    const CommandResult result = run_lancer("--version");
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_NE(result.output.find("lancer 0."), std::string::npos) << result.output;
}

TEST(Cli, UnknownSubcommandIsAUsageError) {
    const CommandResult result = run_lancer("frobnicate");
    EXPECT_EQ(result.exit_code, 2) << result.output;
}

// `check` says which integrator a render of the scene would use: the
// scene's own, or the default when it names none.
TEST(Cli, CheckNamesTheIntegratorARenderWouldUse) {
    const std::string scenes = std::string(LANCER_SOURCE_DIR) + "/scenes/";
    CommandResult result = run_lancer("check " + scenes + "language/meshes.pov");  // names none
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("integrator: whitted (the default: the scene names none)"), std::string::npos)
        << result.output;
    result = run_lancer("check " + scenes + "hard_shadows.pov");  // render_settings names shadow
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("integrator: shadow\n"), std::string::npos) << result.output;
}

// Noise and pattern functions called while parsing are the renderer's,
// with POV-Ray's values (povray 3.7 #debug prints 0.612779047 0.512266456).
TEST(Cli, FunctionsCalledWhileParsingUseTheRenderersNoiseAndPatterns) {
    TempFolder folder;
    const std::string scene = (folder.path() / "noise.pov").string();
    std::ofstream(scene) << "#include \"functions.inc\"\n#declare P = function { pattern { agate } }\n"
                            "#debug concat(str(f_noise3d(0.3, 0.6, 0.9), 0, 9), \" \", str(P(0.3, 0.6, 0.9), 0, 9))\n";
    const CommandResult result = run_lancer("check '" + scene + "'");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("#debug: 0.612779047 0.512266456"), std::string::npos) << result.output;
}

// povray 3.7's #debug of the same lines prints the same digits; octaves past
// int's range count as one there (its int conversion gives INT_MIN).
TEST(Cli, VturbulenceWhileParsingIsPovRays) {
    TempFolder folder;
    const std::string scene = (folder.path() / "vturbulence.pov").string();
    std::ofstream(scene) << "#macro Show(O) #debug concat(vstr(3, vturbulence(2.5, 0.6, O, <1.3, -2.1, 0.4>), "
                            "\",\", 0, 12), \"\\n\") #end\n"
                            "Show(4) Show(1e300) Show(10) Show(25)\n";
    const CommandResult result = run_lancer("check '" + scene + "'");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    for (const char* expected : {"#debug: 0.421749568306,-0.074745779538,-0.509335851621",
                                 "#debug: 0.274151693514,-0.067478113667,-0.308677954094",
                                 "#debug: 0.433020735099,-0.082115171000,-0.466145584035"})
        EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
    // 25 octaves are clamped to POV's 10.
    const std::string ten = "#debug: 0.433020735099,-0.082115171000,-0.466145584035";
    EXPECT_NE(result.output.find(ten, result.output.find(ten) + 1), std::string::npos) << result.output;
}

TEST(Cli, GeometryQueriesWhileParsingAnswerAsPovRay) {
    // povray's #debug of the same lines prints the same numbers.
    TempFolder folder;
    const std::string scene = (folder.path() / "queries.pov").string();
    std::ofstream(scene) << "#declare Ball = sphere { <0, 1, 0>, 1 scale <2, 1, 1> }\n"
                            "#declare N = <9, 9, 9>;\n"
                            "#declare P = trace(Ball, <5, 1, 0>, <-1, 0, 0>, N);\n"
                            "#debug concat(vstr(3, P, \",\", 0, 3), \" \", vstr(3, N, \",\", 0, 3), \" \", "
                            "vstr(3, max_extent(Ball), \",\", 0, 3), \" \", str(inside(Ball, <1.5, 1, 0>), 0, 0))\n";
    const CommandResult check = run_lancer("check '" + scene + "'");
    EXPECT_EQ(check.exit_code, 0) << check.output;
    EXPECT_NE(check.output.find("#debug: 2.000,1.000,0.000 1.000,0.000,0.000 2.000,2.000,1.000 1"), std::string::npos)
        << check.output;
    const CommandResult render = run_lancer("render '" + scene + "' --width 8 --height 8 -q -o '" +
                                            (folder.path() / "queries.png").string() + "'");
    EXPECT_EQ(render.exit_code, 0) << render.output;
    EXPECT_NE(render.output.find("#debug: 2.000,1.000,0.000"), std::string::npos) << render.output;
}

TEST(Cli, DeclarationsAndIncludeFoldersOnEveryCommand) {
    TempFolder folder;
    const std::string scene = (folder.path() / "declared.pov").string();
    std::filesystem::create_directories(folder.path() / "lib");
    std::ofstream((folder.path() / "lib" / "extra.inc").string()) << "#declare FromLib = 3;\n";
    std::ofstream(scene) << "#include \"extra.inc\"\n"
                            "#debug concat(str(Size + FromLib, 0, 2), \" \", Name, \"\\n\")\n"
                            "sphere { 0, Size }\n";
    const std::string inputs = " -D Size=2.5 -D 'Name=\"ball\"' -I '" + (folder.path() / "lib").string() + "'";
    const CommandResult check = run_lancer("check '" + scene + "'" + inputs);
    EXPECT_EQ(check.exit_code, 0) << check.output;
    EXPECT_NE(check.output.find("#debug: 5.50 ball"), std::string::npos) << check.output;
    const CommandResult render = run_lancer("render '" + scene + "'" + inputs + " --width 8 --height 8 -q -o '" +
                                            (folder.path() / "d.png").string() + "'");
    EXPECT_EQ(render.exit_code, 0) << render.output;
    EXPECT_NE(render.output.find("#debug: 5.50 ball"), std::string::npos) << render.output;
    const CommandResult bad = run_lancer("check '" + scene + "' -D Size=abc");
    EXPECT_NE(bad.exit_code, 0);
    EXPECT_NE(bad.output.find("-D expects Name=value"), std::string::npos) << bad.output;
    const CommandResult reserved = run_lancer("check '" + scene + "'" + inputs + " -D sphere=1");
    EXPECT_NE(reserved.exit_code, 0);
    EXPECT_NE(reserved.output.find("reserved word"), std::string::npos) << reserved.output;
}

TEST(Cli, LanguageVersionStandsInForAMissingVersionDirective) {
    // POV-Ray's +MV: a scene with no #version is 3.62 (legacy gamma, with a
    // warning) unless the command line says which version it is.
    TempFolder folder;
    const std::string scene = (folder.path() / "unversioned.pov").string();
    std::ofstream(scene) << "#debug concat(str(version, 0, 2), \"\\n\")\nsphere { 0, 1 }\n";
    const CommandResult bare = run_lancer("check '" + scene + "'");
    EXPECT_EQ(bare.exit_code, 0) << bare.output;
    EXPECT_NE(bare.output.find("#debug: 3.70"), std::string::npos) << bare.output;
    EXPECT_NE(bare.output.find("gamma correction is turned off"), std::string::npos) << bare.output;
    const CommandResult as_3_7 = run_lancer("check '" + scene + "' --language-version 3.7");
    EXPECT_EQ(as_3_7.exit_code, 0) << as_3_7.output;
    EXPECT_EQ(as_3_7.output.find("gamma correction is turned off"), std::string::npos) << as_3_7.output;
    const CommandResult as_3_5 = run_lancer("check '" + scene + "' --language-version 3.5");
    EXPECT_NE(as_3_5.output.find("#debug: 3.50"), std::string::npos) << as_3_5.output;
    EXPECT_NE(as_3_5.output.find("pre-3.7 scene"), std::string::npos) << as_3_5.output;
    const CommandResult bad = run_lancer("check '" + scene + "' --language-version 0");
    EXPECT_NE(bad.exit_code, 0);
    EXPECT_NE(bad.output.find("--language-version"), std::string::npos) << bad.output;
}

}  // namespace lancer::test
