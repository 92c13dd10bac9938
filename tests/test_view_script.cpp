// The viewer's script (`texfilter view --script FILE`, host/view/script.h): every action parses to the
// values it names, comments and blank lines are skipped with the line numbers kept, every bad line is an
// error naming FILE:LINE and what is wrong, and the bounds are where the contract puts them. CPU only.
#include "support.h"
#include "view/screenshot_files.h"
#include "view/script.h"
#include <filesystem>
#include <fstream>
#include <sys/stat.h>

using namespace tf;

namespace {

// The tf::Error message of parse_script(text), "" if it parsed.
std::string error_of(const std::string& text, const std::string& name = "views.txt")
{
    try {
        parse_script(text, name);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// The message for `line` at line 3 of a script whose first two lines are good ("" if it parsed): a bad line's
// names views.txt:3 and what is wrong.
std::string error_at_line_3(const std::string& line)
{
    return error_of("scene plane\n# a comment\n" + line + "\nquit\n");
}

// The message for a script of `line` alone: "" for a good line.
std::string error_of_line(const std::string& line) { return error_of(line + "\n"); }

const char* const kEveryAction = R"(# every action once
scene tunnel
texture checker --texture-size 64
filter ewa --alpha 3 --max-aniso 8 --taps hardware
compare aniso --probes 4 --aniso-shape feline
resize 640x480
wait 10

camera reset
camera set 1.5,-2,0.25,90,-10
camera fly 0.5 0 -1
camera turn 15 -5
camera orbit -30 2.5
animate on
frame 12
view lod
truth on
divider 0.25
loupe 100 50 8
loupe off
cursor 320 240
minimize
restore
hold 500
stage compute
derivatives ray
screenshot out/a.png   # the scene as shown
screenshot-ui out/ui.png
ui off
compare off
quit
)";

} // namespace

TEST_SUITE_BEGIN("reference");

// 1. Every action of the contract, in one script: verbs, line numbers and the typed values.
TEST_CASE("every-action")
{
    const std::vector<ScriptAction> a = parse_script(kEveryAction, "every.txt");
    CHECK_EQ(a.size(), 29);
    if (a.size() != 29)
        return;
    CHECK(a[0].verb == "scene" && a[0].line == 2 && script_scene(a[0]) == SceneKind::tunnel);
    const TextureSource t = script_texture(a[1]);
    CHECK(t.name_or_path == "checker" && t.procedural_size == 64 && t.color == ColorSpace::automatic);
    const SamplerOptions f = script_sampler(a[2]);
    CHECK(f.filter == Filter::ewa && f.alpha == 3.0f && f.max_aniso == 8.0f && f.taps == Taps::hardware);
    const SamplerOptions c = script_sampler(a[3]);
    CHECK(c.filter == Filter::aniso && c.probes == 4 && c.aniso_shape == AnisoShape::feline);
    CHECK(!script_off(a[3]));
    CHECK(script_size(a[4]) == std::make_pair(640, 480));
    CHECK(script_count(a[5]) == 10);
    CHECK(a[6].verb == "camera" && a[6].line == 9 && script_word(a[6]) == "reset"); // line 8 was blank
    const Camera pose = script_camera_pose(a[7]);
    CHECK(pose.position == glm::dvec3(1.5, -2, 0.25) && pose.yaw == 90 && pose.pitch == -10);
    CHECK(script_camera_motion(a[8]) == (std::vector<double>{0.5, 0, -1}));
    CHECK(script_word(a[9]) == "turn" && script_camera_motion(a[9]) == (std::vector<double>{15, -5}));
    CHECK(script_word(a[10]) == "orbit" && script_camera_motion(a[10]) == (std::vector<double>{-30, 2.5}));
    CHECK(a[11].verb == "animate" && !script_off(a[11]));
    CHECK(script_count(a[12]) == 12);
    CHECK(script_word(a[13]) == "lod");
    CHECK(a[14].verb == "truth" && !script_off(a[14]));
    CHECK_EQ(script_divider(a[15]), 0.25);
    CHECK(script_loupe(a[16]) == (std::array<int, 3>{100, 50, 8}));
    CHECK(script_off(a[17]));
    CHECK(script_cursor(a[18]) == (std::array<int, 2>{320, 240}));
    CHECK(a[19].verb == "minimize" && a[20].verb == "restore" && a[19].words.empty());
    CHECK(script_count(a[21]) == 500);
    CHECK(script_stage(a[22]) == Stage::compute);
    CHECK(script_gradients(a[23]) == Gradients::ray);
    CHECK(script_path(a[24]) == "out/a.png" && a[24].words.size() == 1); // the trailing comment dropped
    CHECK(script_path(a[25]) == "out/ui.png" && a[25].verb == "screenshot-ui");
    CHECK(a[26].verb == "ui" && script_off(a[26]));
    CHECK(a[27].verb == "compare" && script_off(a[27]));
    CHECK(a[28].verb == "quit" && a[28].line == 31);
    // close ends a script as quit does (it is the window's close button): nothing may follow it.
    CHECK(parse_script("wait 1\nclose\n", "close.txt").back().verb == "close");
    CHECK_THROWS_WITH(parse_script("close\nwait 1\n", "close.txt"), "close.txt:2: 'wait' after close");
}

// 2. Comments, blank lines, tabs and CRLF line ends: skipped or split, the line numbers those of the file.
TEST_CASE("comments-and-lines")
{
    const std::vector<ScriptAction> a =
        parse_script("\r\n   # indented comment\n\n\tfilter\tbilinear   --wrap  clamp\r\n#\nwait 3 # three frames\r\n",
                     "crlf.txt");
    CHECK_EQ(a.size(), 2);
    if (a.size() != 2)
        return;
    CHECK(a[0].line == 4 && a[0].verb == "filter" && a[0].words == (std::vector<std::string>{"bilinear", "--wrap", "clamp"}));
    CHECK(script_sampler(a[0]).wrap == Wrap::clamp);
    CHECK(a[1].line == 6 && a[1].words == std::vector<std::string>{"3"});
    CHECK(parse_script("", "empty.txt").empty());
    CHECK(parse_script("# only a comment\n\n", "empty.txt").empty());
}

// 3. Each bad line is refused at its own line, naming what is wrong.
TEST_CASE("errors-name-the-line")
{
    CHECK_CONTAINS(error_at_line_3("fly away"), "views.txt:3: ", "unknown action 'fly'");
    CHECK_CONTAINS(error_at_line_3("scene nowhere"), "views.txt:3: ", "nowhere");
    CHECK_CONTAINS(error_at_line_3("scene"), "views.txt:3: ", "scene S");
    CHECK_CONTAINS(error_at_line_3("texture"), "views.txt:3: ", "missing");
    CHECK_CONTAINS(error_at_line_3("texture --linear"), "views.txt:3: ",
                   "missing its first word before any flag (T|PATH)");
    CHECK_CONTAINS(error_at_line_3("filter --band 0.5"), "views.txt:3: ", "missing its first word before any flag (F)");
    CHECK_CONTAINS(error_at_line_3("texture checker --texture-size 0"), "views.txt:3: ", "--texture-size");
    CHECK_CONTAINS(error_at_line_3("texture checker --filter ewa"), "views.txt:3: ", "unknown flag --filter");
    // A line sets the whole half or texture: a flag it does not read is refused as render refuses it, but for
    // what the viewer's own views read (the LOD view: --lod-*; the error view's truth: --spp, --pixel-filter).
    CHECK_CONTAINS(error_at_line_3("texture checker --linear"), "views.txt:3: ",
                   "--linear is not read by --texture checker");
    // A file is checked when the line runs: a screenshot may write it.
    CHECK_EQ_TEXT(error_of_line("texture not-yet-written.png"), "");
    CHECK_CONTAINS(error_at_line_3("filter trilinear --probes 4"), "views.txt:3: ",
                   "--probes is not read by --filter trilinear (it applies to aniso)");
    CHECK_CONTAINS(error_at_line_3("compare bilinear --alpha 3"), "views.txt:3: ",
                   "--alpha is not read by --filter bilinear (it applies to ewa)");
    CHECK_EQ_TEXT(error_of_line("filter nearest --lod-bias 1"), "");
    CHECK_EQ_TEXT(error_of_line("filter trilinear --spp 16 --pixel-filter gaussian"), "");
    CHECK_CONTAINS(error_at_line_3("filter ewa --alpha 0x10"), "views.txt:3: ", "bad value for --alpha: '0x10'");
    CHECK_CONTAINS(error_at_line_3("wait 0x10"), "views.txt:3: ", "'0x10' is not a whole number");
    CHECK_CONTAINS(error_at_line_3("divider inf"), "views.txt:3: ", "'inf' is not a finite number");
    CHECK_CONTAINS(error_at_line_3("filter"), "views.txt:3: ", "missing");
    CHECK_CONTAINS(error_at_line_3("filter blurry"), "views.txt:3: ", "blurry");
    CHECK_CONTAINS(error_at_line_3("filter ewa --alpha 99"), "views.txt:3: ", "--alpha");
    CHECK_CONTAINS(error_at_line_3("filter ewa --bogus 1"), "views.txt:3: ", "unknown flag --bogus");
    // the viewer draws with Vulkan
    CHECK_CONTAINS(error_at_line_3("filter ewa --backend reference"), "views.txt:3: ", "unknown flag --backend");
    CHECK_CONTAINS(error_at_line_3("filter ground-truth --spp 50"), "views.txt:3: ", "square");
    CHECK_CONTAINS(error_at_line_3("filter trilinear --lod-min 3 --lod-max 1"), "views.txt:3: ", "--lod-min");
    CHECK_CONTAINS(error_at_line_3("filter ewa --alpha"), "views.txt:3: ", "needs a value");
    CHECK_CONTAINS(error_at_line_3("compare bogus"), "views.txt:3: ", "bogus");
    // not the single word off
    CHECK_CONTAINS(error_at_line_3("compare off now"), "views.txt:3: ", "unexpected argument 'now'");
    CHECK_CONTAINS(error_at_line_3("resize 640x"), "views.txt:3: ", "640x");
    CHECK_CONTAINS(error_at_line_3("resize 641x480"), "views.txt:3: ", "even");
    CHECK_CONTAINS(error_at_line_3("resize 640 480"), "views.txt:3: ", "resize WxH");
    CHECK_CONTAINS(error_at_line_3("wait"), "views.txt:3: ", "wait N");
    CHECK_CONTAINS(error_at_line_3("wait 1.5"), "views.txt:3: ", "'1.5' is not a whole number");
    CHECK_CONTAINS(error_at_line_3("screenshot out.jpg"), "views.txt:3: ", ".png");
    CHECK_CONTAINS(error_at_line_3("screenshot"), "views.txt:3: ", "PATH.png");
    CHECK_CONTAINS(error_at_line_3("screenshot-ui a.png b.png"), "views.txt:3: ", "PATH.png");
    CHECK_CONTAINS(error_at_line_3("quit now"), "views.txt:3: ", "quit");
    CHECK_CONTAINS(error_at_line_3("camera"), "views.txt:3: ", "reset, set, fly, turn or orbit");
    CHECK_CONTAINS(error_at_line_3("camera zoom 2"), "views.txt:3: ", "unknown camera action 'zoom'");
    CHECK_CONTAINS(error_at_line_3("camera reset now"), "views.txt:3: ", "camera reset");
    CHECK_CONTAINS(error_at_line_3("camera set 1,2,3,4"), "views.txt:3: ", "X,Y,Z,YAW,PITCH");
    // tf::parse_camera's words, as render --camera's
    CHECK_CONTAINS(error_at_line_3("camera set 1,2,3,4,nan"), "views.txt:3: ", "PITCH 'nan' is not a number");
    CHECK_CONTAINS(error_at_line_3("camera set 0,0,0,0,90"), "views.txt:3: ", "PITCH");
    CHECK_CONTAINS(error_at_line_3("camera set 1 2 3 4 5"), "views.txt:3: ", "camera set X,Y,Z,YAW,PITCH");
    CHECK_CONTAINS(error_at_line_3("camera fly 1 2"), "views.txt:3: ", "camera fly DX DY DZ");
    CHECK_CONTAINS(error_at_line_3("camera turn 1 x"), "views.txt:3: ", "'x' is not a finite number");
    CHECK_CONTAINS(error_at_line_3("camera orbit 1 inf"), "views.txt:3: ", "'inf' is not a finite number");
    CHECK_CONTAINS(error_at_line_3("animate maybe"), "views.txt:3: ", "on or off");
    CHECK_CONTAINS(error_at_line_3("truth"), "views.txt:3: ", "on|off");
    CHECK_CONTAINS(error_at_line_3("view depth"), "views.txt:3: ", "unknown view 'depth'");
    CHECK_CONTAINS(error_at_line_3("divider half"), "views.txt:3: ", "'half' is not a finite number");
    CHECK_CONTAINS(error_at_line_3("loupe 10 10"), "views.txt:3: ", "loupe X Y ZOOM");
    CHECK_CONTAINS(error_at_line_3("loupe 10 10 2.5"), "views.txt:3: ", "zoom '2.5'");
    CHECK_CONTAINS(error_at_line_3("cursor 1"), "views.txt:3: ", "cursor X Y");
    CHECK_CONTAINS(error_at_line_3("cursor 1 y"), "views.txt:3: ", "pixel y 'y'");
    CHECK_CONTAINS(error_at_line_3("minimize now"), "views.txt:3: ", "minimize");
    CHECK_CONTAINS(error_at_line_3("restore 1"), "views.txt:3: ", "restore");
    CHECK_CONTAINS(error_at_line_3("stage vertex"), "views.txt:3: ", "fragment|compute");
    CHECK_CONTAINS(error_at_line_3("derivatives fast"), "views.txt:3: ", "fine|coarse|ray");
    CHECK_CONTAINS(error_at_line_3("frame x"), "views.txt:3: ", "frame 'x'");

    // Nothing may follow quit: it would never run.
    const std::string after = error_of("wait 1\nquit\n\nwait 2\n");
    CHECK_CONTAINS(after, "views.txt:4: ", "after quit (line 2)");
    // The first bad line is the one named, and the file's name is what was given.
    const std::string first = error_of("wait x\nwait y\n", "/tmp/other.script");
    CHECK_CONTAINS(first, "/tmp/other.script:1: wait: ");
}

// 4. The bounds: each limit accepted, one past it refused.
TEST_CASE("bounds")
{
    const char* const accepted[] = {
        "wait 0",
        "wait 100000",
        "hold 0",
        "hold 60000",
        "divider 0",
        "divider 1",
        "loupe 0 0 1",
        "loupe 65535 65535 64",
        "resize 2x2",
        "resize 8192x8192",
        "frame 0",
        "frame 1073741824",
        "texture grid --texture-size 16384",
        "filter aniso --probes 16",
        "filter ground-truth --spp 4096 --pixel-filter gaussian",
    };
    for (const char* line : accepted) {
        INFO(line);
        CHECK_EQ_TEXT(error_of_line(line), "");
    }
    // Each refused line and what its message names.
    const char* const refused[][2] = {
        {"wait 100001", "0..100000"},
        {"wait -1", "0..100000"},
        {"hold 60001", "0..60000"},
        {"divider 1.0001", "0..1"},
        {"divider -0.0001", "0..1"},
        {"loupe 0 0 0", "1..64"},
        {"loupe 0 0 65", "1..64"},
        {"loupe -1 0 4", "pixel x '-1'"},
        {"resize 8194x8", "[2, 8192]"},
        {"resize 0x8", "[2, 8192]"},
        {"frame -1", "0..1073741824"},
        {"texture grid --texture-size 16385", "--texture-size"},
        {"filter aniso --probes 17", "--probes"},
        {"filter ground-truth --spp 4225", "--spp"},
    };
    for (const auto& [line, part] : refused) {
        INFO(line);
        CHECK_CONTAINS(error_at_line_3(line), "views.txt:3: ", part);
    }
}

// 5. From a file: the same actions; a missing file names its path.
TEST_CASE("file")
{
    const std::filesystem::path work = test::make_work_dir("view-script");
    const std::string path = (work / "every.txt").string();
    std::ofstream(path) << kEveryAction;
    const std::vector<ScriptAction> from_file = read_script(path), from_text = parse_script(kEveryAction, path);
    CHECK_EQ(from_file.size(), from_text.size());
    for (size_t i = 0; i < std::min(from_file.size(), from_text.size()); ++i)
        CHECK(from_file[i].line == from_text[i].line && from_file[i].verb == from_text[i].verb &&
                  from_file[i].words == from_text[i].words,
              "action " + std::to_string(i));
    const std::string missing = (work / "missing.txt").string();
    CHECK_THROWS_WITH(read_script(missing), missing + ": cannot open the script (No such file or directory)");
    // Read from a regular file only, up to 16 MiB: a FIFO is refused without waiting for a writer, an oversized
    // file from its size (sparse here: nothing is written).
    const std::string fifo = (work / "fifo.txt").string();
    CHECK(mkfifo(fifo.c_str(), 0600) == 0);
    CHECK_THROWS_WITH(read_script(fifo), fifo + ": is a pipe (FIFO), not a regular file (the script must be one)");
    const std::string big = (work / "big.txt").string();
    std::ofstream(big) << kEveryAction;
    std::filesystem::resize_file(big, (16u << 20) + 1);
    CHECK_THROWS_WITH(read_script(big), big + ": the script is 16.0 MiB (16777217 bytes), over its cap of 16.0 MiB (16777216 bytes)");
    std::ofstream(work / "bad.txt") << "wait 1\nwiat 2\n";
    CHECK_THROWS_WITH(read_script((work / "bad.txt").string()), (work / "bad.txt").string() + ":2: unknown action 'wiat'");
}

// 6. A typed helper on an action of another verb is an error naming the line, not a wrong value.
TEST_CASE("helpers-check-the-verb")
{
    const std::vector<ScriptAction> a = parse_script("wait 5\ncamera fly 1 2 3\ncamera reset\n", "h.txt");
    CHECK_EQ(a.size(), 3);
    if (a.size() != 3)
        return;
    CHECK_THROWS_WITH(script_sampler(a[0]), "script line 1: script_sampler does not apply to 'wait'");
    CHECK_THROWS_WITH(script_size(a[0]), "script line 1");
    CHECK_THROWS_WITH(script_camera_pose(a[1]), "script line 2: camera: not 'camera set");
    CHECK_THROWS_WITH(script_camera_motion(a[2]), "script line 3: camera: not 'camera fly'");
    CHECK_THROWS_WITH(script_off(a[0]), "script_off does not apply to 'wait'");
}

// 7. The dynamic texture's actions: texture-animate on|off and texture-frame N (0..1000000, as render's
//    --texture-frame), with their errors at their lines.
TEST_CASE("texture-frame-actions")
{
    const std::vector<ScriptAction> a =
        parse_script("texture dynamic --texture-size 128\ntexture-animate off\ntexture-frame 40\ntexture-animate on\n"
                     "texture-frame 0\ntexture-frame 1000000\n",
                     "dynamic.txt");
    CHECK_EQ(a.size(), 6);
    if (a.size() != 6)
        return;
    CHECK(script_texture(a[0]).name_or_path == "dynamic");
    CHECK(a[1].verb == "texture-animate" && script_off(a[1]));
    CHECK(a[2].verb == "texture-frame" && a[2].line == 3 && script_count(a[2]) == 40);
    CHECK(a[3].verb == "texture-animate" && !script_off(a[3]));
    CHECK(script_count(a[4]) == 0);
    CHECK(script_count(a[5]) == 1000000);
    CHECK_CONTAINS(error_at_line_3("texture-frame"), "views.txt:3: ", "texture-frame N");
    CHECK_CONTAINS(error_at_line_3("texture-frame 1 2"), "views.txt:3: ", "texture-frame N");
    CHECK_CONTAINS(error_at_line_3("texture-frame -1"), "views.txt:3: ",
                   "texture frame '-1' is not a whole number in 0..1000000");
    CHECK_CONTAINS(error_at_line_3("texture-frame 1000001"), "views.txt:3: ", "0..1000000");
    CHECK_CONTAINS(error_at_line_3("texture-frame 2.5"), "views.txt:3: ", "texture frame '2.5'");
    CHECK_CONTAINS(error_at_line_3("texture-animate"), "views.txt:3: ", "on|off");
    CHECK_CONTAINS(error_at_line_3("texture-animate maybe"), "views.txt:3: ", "on or off");
    CHECK_CONTAINS(error_at_line_3("texture-animte on"), "views.txt:3: ", "unknown action 'texture-animte'");
    // The camera path's frame keeps its own bounds: the two counters are not confused.
    CHECK_EQ_TEXT(error_of_line("frame 1000001"), "");
    // The texture action takes no frame: that is texture-frame's (its words are render's texture flags).
    CHECK_CONTAINS(error_at_line_3("texture dynamic --texture-frame 3"), "views.txt:3: ",
                   "unknown flag --texture-frame");
}

// 8. A screenshot's files (PATH.png, .txt, .json) never replace a file the viewer did not write: each one that
// exists is refused by name, before anything is written; one this viewer wrote (remember_written) may be
// replaced, but not a file put in its place since.
TEST_CASE("screenshot-files")
{
    const std::filesystem::path work = test::make_work_dir("view-screenshot-files");
    const std::string png = (work / "notes.png").string(), txt = (work / "notes.txt").string(),
                      json = (work / "notes.json").string();
    CHECK(checked_screenshot_paths(png, false, {}) == png);
    for (const std::string& theirs : {png, txt, json}) {
        std::ofstream(theirs) << "someone's notes\n";
        CHECK_THROWS_WITH(checked_screenshot_paths(png, false, {}),
                          theirs + ": exists, and this viewer did not write it: a screenshot replaces no file it "
                                   "did not create (remove it, or choose another name)");
        std::filesystem::remove(theirs);
    }
    // The whole window's screenshot writes the .png alone: the .txt and .json beside it are not its concern.
    std::ofstream(txt) << "someone's notes\n";
    CHECK(checked_screenshot_paths(png, true, {}) == png);
    // The files of an earlier screenshot in the same run are replaced.
    WrittenFiles written;
    std::ofstream(png) << "png";
    std::ofstream(json) << "{}";
    for (const std::string& ours : {png, txt, json})
        remember_written(written, ours);
    CHECK(checked_screenshot_paths(png, false, {}, written) == png);
    // Not once another file took the place of one of them (as an editor saves: a new file renamed over it).
    std::ofstream(txt + ".new") << "someone's notes\n";
    std::filesystem::rename(txt + ".new", txt);
    CHECK_THROWS_WITH(checked_screenshot_paths(png, false, {}, written), txt + ": exists, and this viewer did not");
    // A symbolic link is something there too, even one that leads nowhere.
    std::filesystem::remove_all(work);
    std::filesystem::create_directories(work);
    std::filesystem::create_symlink(work / "nowhere.json", json);
    CHECK_THROWS_WITH(checked_screenshot_paths(png, false, {}), json + ": exists");
    // The panel's and F12's name: the next stem none of whose three files exists.
    CHECK(unused_screenshot_path(png) == (work / "notes-1.png").string());
}

TEST_SUITE_END();
