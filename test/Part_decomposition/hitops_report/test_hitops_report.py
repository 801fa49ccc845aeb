"""The progress and the report of hitops --batch, as a user sees them.

usage: test_hitops_report.py HITOPS DATA_DIR WORK_DIR progress|report|chromium

progress: a batch on a pseudo-terminal keeps one status line that advances and ends with the right
counts; on a pipe it prints one line per mesh; --quiet and shards. report: report.html has one entry
per mesh, working links and thumbnails that decode with the expected size and colours. chromium:
headless Chromium shows the thumbnails (exit 77, skipped, without /usr/bin/chromium). ctest runs
the three (tests hitops_progress, hitops_report, hitops_report_chromium).
"""

import html.parser
import os
import pty
import re
import shutil
import subprocess
import sys
import urllib.parse

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_decode import read_png, saturation  # noqa: E402

SKIPPED = 77
HITOPS, DATA, WORK = (os.path.abspath(a) for a in sys.argv[1:4]) if len(sys.argv) > 3 else (None, None, None)
CHROMIUM = os.environ.get("PD_CHROMIUM", "/usr/bin/chromium")  # another path: to try the skip
STATUS = re.compile(r"\[(\d+)/(\d+)\] (\d+) failed, (\d+) timed out \| ")


def make_list(name, meshes):
    """A list file of the shipped meshes (names without .off) and a missing one (None)."""
    path = os.path.join(WORK, name + ".txt")
    with open(path, "w") as f:
        for m in meshes:
            f.write((os.path.join(DATA, m + ".off") if m else os.path.join(WORK, "missing.off")) + "\n")
    return path


def fresh(name):
    path = os.path.join(WORK, name)
    shutil.rmtree(path, ignore_errors=True)
    return path


def run_on_pty(arguments):
    """hitops with stderr (and stdin) on a pseudo-terminal: (status, stdout, what the terminal got)."""
    master, slave = pty.openpty()
    process = subprocess.Popen([HITOPS] + arguments, stdin=slave, stdout=subprocess.PIPE, stderr=slave)
    os.close(slave)
    terminal = b""
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:  # EIO: the child closed the terminal
            break
        if not chunk:
            break
        terminal += chunk
    os.close(master)
    out = process.stdout.read().decode()
    process.stdout.close()
    return process.wait(timeout=120), out, terminal.decode()


def run_on_pipe(arguments):
    p = subprocess.run([HITOPS] + arguments, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120)
    return p.returncode, p.stdout.decode(), p.stderr.decode()


BATCH = ["dumbbell", None, "animal", "table"]


def test_terminal_status_line_advances_and_ends_with_the_counts():
    status, out, terminal = run_on_pty(["--batch", make_list("pty", BATCH), "--out", fresh("pty_out"), "--threads", "2"])
    assert status == 1, status  # the missing mesh
    assert out == "batch: 3 decomposed, 0 skipped, 1 failed, 0 timed out\n", out
    # every state of the line is drawn after '\r' + clear to the end of the line
    states = [s for s in terminal.split("\r\x1b[K") if s]
    done = [int(STATUS.match(s).group(1)) for s in states if STATUS.match(s)]
    assert done == sorted(done), done
    assert len(set(done)) >= 2, states  # it advances
    assert any("| dumbbell" in s for s in states), states  # the current mesh
    assert any("left" in s for s in states), states  # the time left
    last = states[-1]
    assert last.startswith("[4/4] 1 failed, 0 timed out | ") and last.endswith("elapsed, done\r\n"), repr(last)
    # the error of the missing mesh on a line of its own
    assert any(s.startswith("hitops: " + os.path.join(WORK, "missing.off")) and s.endswith("\r\n") for s in states)


def test_terminal_status_line_with_a_child_process_per_mesh():
    status, out, terminal = run_on_pty(["--batch", make_list("pty_child", ["dumbbell", "animal"]), "--out",
                                        fresh("pty_child_out"), "--threads", "2", "--mesh-timeout", "120"])
    assert status == 0, status
    states = [s for s in terminal.split("\r\x1b[K") if s]
    assert states[-1].startswith("[2/2] 0 failed, 0 timed out | "), states
    # a timed-out mesh counts as such
    status, out, terminal = run_on_pty(["--batch", make_list("pty_timeout", ["table"]), "--out", fresh("pty_timeout_out"),
                                        "--mesh-timeout", "0.001"])
    assert status == 1
    states = [s for s in terminal.split("\r\x1b[K") if s]
    assert states[-1].startswith("[1/1] 0 failed, 1 timed out | "), states


def test_pipe_one_line_per_mesh():
    status, out, err = run_on_pipe(["--batch", make_list("pipe", BATCH), "--out", fresh("pipe_out"), "--threads", "2"])
    assert status == 1
    assert "\r" not in err and "\x1b" not in err, repr(err)
    lines = err.splitlines()
    assert len(lines) == 4, lines
    for k, (line, name) in enumerate(zip(lines, ["dumbbell", "missing", "animal", "table"]), 1):
        assert line.startswith("[%d/4] %s: " % (k, name)), line
    assert re.fullmatch(r"\[1/4\] dumbbell: ok, \d+ faces, \d+ parts, [0-9.]+ s", lines[0]), lines[0]
    assert lines[1].startswith("[2/4] missing: failed, ") and "missing.off" in lines[1], lines[1]
    # skipped on the second run
    status, out, err = run_on_pipe(["--batch", make_list("pipe", BATCH), "--out", os.path.join(WORK, "pipe_out")])
    assert err.splitlines()[0] == "[1/4] dumbbell: skipped, already done", err


def test_quiet_leaves_only_the_errors():
    for run in (run_on_pty, run_on_pipe):
        status, out, err = run(["--batch", make_list("quiet", BATCH), "--out", fresh("quiet_out"), "--threads", "2",
                                "--quiet"])
        assert status == 1
        assert err.replace("\r\n", "\n") == "hitops: %s: cannot open '%s'\n" % ((os.path.join(WORK, "missing.off"),) * 2), \
            repr(err)


def test_shards_report_their_own_share():
    status, out, err = run_on_pipe(["--batch", make_list("shard", BATCH), "--out", fresh("shard_out"), "--shard", "1/2"])
    assert status == 1  # the missing mesh is of this shard
    names = [l.split(":")[0] for l in err.splitlines()]
    assert names == ["[1/2] missing", "[2/2] table"], names


def test_one_mesh_prints_no_stage_line_when_fast_or_not_on_a_terminal():
    png = os.path.join(WORK, "one.png")
    status, out, terminal = run_on_pty([os.path.join(DATA, "dumbbell.off"), "--thumbnail", png, "--threads", "2"])
    assert status == 0 and terminal == "", repr(terminal)  # under a second
    status, out, err = run_on_pipe([os.path.join(DATA, "dumbbell.off"), "--thumbnail", png, "--thumbnail-size", "200x90"])
    assert status == 0 and err == "", err
    width, height, pixels = read_png(png)
    assert (width, height) == (200, 90)


class Report_parser(html.parser.HTMLParser):
    """The figures of report.html: per figure its id, class, images, links and text."""

    def __init__(self):
        super().__init__()
        self.figures, self.scripts, self.current = [], 0, None

    def handle_starttag(self, tag, attributes):
        a = dict(attributes)
        if tag == "script" or (tag == "link" and a.get("rel") == "stylesheet"):
            self.scripts += 1
        if tag == "figure":
            self.current = {"id": a.get("id"), "class": a.get("class", "").split(), "img": [], "href": [], "text": "",
                            "error": False}
            self.figures.append(self.current)
        elif self.current is not None:
            if tag == "img":
                self.current["img"].append(a)
            elif tag == "a":
                self.current["href"].append(a["href"])
            elif tag == "div" and "error" in a.get("class", ""):
                self.current["error"] = True

    def handle_endtag(self, tag):
        if tag == "figure":
            self.current = None

    def handle_data(self, data):
        if self.current is not None:
            self.current["text"] += data


def run_report_batch(name):
    out = fresh(name)
    status, stdout, err = run_on_pipe(["--batch", make_list(name, BATCH), "--out", out, "--report", "--threads", "2"])
    assert status == 1, err
    return out


def summary_parts(out):
    with open(os.path.join(out, "summary.tsv")) as f:
        rows = [line.rstrip("\n").split("\t") for line in f][1:]
    return {r[0]: int(r[4]) for r in rows if r[2] == "ok"}


def test_report_one_entry_per_mesh_working_links_and_thumbnails():
    out = run_report_batch("report")
    with open(os.path.join(out, "report.html"), encoding="utf-8") as f:
        parser = Report_parser()
        parser.feed(f.read())
    assert parser.scripts == 0
    assert [f["id"] for f in parser.figures] == ["dumbbell", "missing", "animal", "table"]
    parts = summary_parts(out)
    for figure in parser.figures:
        for href in figure["href"] + [i["src"] for i in figure["img"]]:
            assert not urllib.parse.urlparse(href).scheme, href  # relative: opens offline
            target = os.path.normpath(os.path.join(out, urllib.parse.unquote(href)))
            assert os.path.isfile(target), href
        if figure["id"] == "missing":
            assert "failed" in figure["class"] and figure["error"] and not figure["img"]
            assert "cannot open" in figure["text"], figure["text"]
            continue
        name = figure["id"]
        assert sorted(os.path.basename(h) for h in figure["href"]) == sorted(
            [name + ".off", name + ".seg", name + ".json", name + ".png"]), figure["href"]
        assert "%d parts" % parts[name] in figure["text"] and "faces" in figure["text"], figure["text"]
        (img,) = figure["img"]
        width, height, pixels = read_png(os.path.join(out, img["src"]))
        assert (width, height) == (int(img["width"]), int(img["height"])) == (320, 160)
        check_thumbnail(pixels, parts[name])


def check_thumbnail(pixels, parts):
    """Left half: the input in grey; right half: the parts in at least `parts` colours."""
    width = len(pixels[0])
    left = {p for row in pixels for p in row[:width // 2]}
    right = {p for row in pixels for p in row[width // 2:]}
    assert len(right) >= parts
    assert max(saturation(p) for p in left) < 10, "the input is grey"
    # the parts' hues: saturated pixels binned by their normalized colour
    hues = {tuple(round(6 * c / max(p)) for c in p) for p in right if saturation(p) > 60}
    assert len(hues) >= min(parts, 3), hues


def test_report_of_a_second_run_keeps_the_pictures():
    out = run_report_batch("rerun")
    os.remove(os.path.join(out, "thumbnails", "animal.png"))
    status, stdout, err = run_on_pipe(["--batch", make_list("rerun", BATCH), "--out", out, "--report"])
    with open(os.path.join(out, "report.html"), encoding="utf-8") as f:
        parser = Report_parser()
        parser.feed(f.read())
    animal = [f for f in parser.figures if f["id"] == "animal"][0]
    assert "skipped" in animal["class"] and animal["img"], animal  # drawn again from the label file
    width, height, pixels = read_png(os.path.join(out, "thumbnails", "animal.png"))
    check_thumbnail(pixels, summary_parts(os.path.join(WORK, "report"))["animal"])


def test_chromium_shows_the_thumbnails():
    out = run_report_batch("chromium")
    shot = os.path.join(WORK, "chromium_screenshot.png")
    if os.path.exists(shot):
        os.remove(shot)
    # root needs --no-sandbox; a profile of its own keeps runs apart
    subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                    "--force-device-scale-factor=1", "--user-data-dir=" + os.path.join(WORK, "chromium_profile"),
                    "--screenshot=" + shot, "--window-size=1400,900",
                    "file://" + urllib.parse.quote(os.path.join(out, "report.html"))],
                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120, check=True)
    width, height, screen = read_png(shot)
    on_screen = {p for row in screen for p in row}
    for name in ("dumbbell", "animal", "table"):
        _, _, pixels = read_png(os.path.join(out, "thumbnails", name + ".png"))
        # the most frequent part colours of the thumbnail are on the screen, give or take rounding
        counts = {}
        for row in pixels:
            for p in row[len(row) // 2:]:
                if saturation(p) > 60:
                    counts[p] = counts.get(p, 0) + 1
        common = sorted(counts, key=counts.get, reverse=True)[:5]
        assert common, name
        for c in common:
            assert c in on_screen or any(max(abs(a - b) for a, b in zip(c, s)) <= 3 for s in on_screen), (name, c)


TESTS = {
    "progress": [test_terminal_status_line_advances_and_ends_with_the_counts,
                 test_terminal_status_line_with_a_child_process_per_mesh, test_pipe_one_line_per_mesh,
                 test_quiet_leaves_only_the_errors, test_shards_report_their_own_share,
                 test_one_mesh_prints_no_stage_line_when_fast_or_not_on_a_terminal],
    "report": [test_report_one_entry_per_mesh_working_links_and_thumbnails,
               test_report_of_a_second_run_keeps_the_pictures],
    "chromium": [test_chromium_shows_the_thumbnails],
}


def main():
    if len(sys.argv) != 5 or sys.argv[4] not in TESTS:
        sys.exit(__doc__)
    if sys.argv[4] == "chromium" and not os.access(CHROMIUM, os.X_OK):
        print("skipped: %s is not installed (apt-get install chromium)" % CHROMIUM)
        sys.exit(SKIPPED)
    os.makedirs(WORK, exist_ok=True)
    failed = 0
    for test in TESTS[sys.argv[4]]:
        try:
            test()
            print("PASS", test.__name__)
        except Exception as e:  # noqa: BLE001 - every failure is reported, then the next test runs
            failed += 1
            print("FAIL", test.__name__, type(e).__name__, e)
    print("%d passed, %d failed" % (len(TESTS[sys.argv[4]]) - failed, failed))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
