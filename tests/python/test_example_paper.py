"""examples/python/paper.py runs (healthy and faulty 0.5 s paper runs) and writes its figure."""
import os
import struct
import subprocess
import sys


def test_the_paper_example_writes_its_two_panel_figure(tmp_path):
    root = os.environ["GEARSIM_SOURCE_DIR"]
    png = tmp_path / "paper.png"
    done = subprocess.run([sys.executable, os.path.join(root, "examples", "python", "paper.py"), str(png)], cwd=root,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    data = png.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", data[16:24])  # the IHDR chunk
    assert (width, height) == (990, 825)  # figsize 9 × 7.5 in, saved at 110 dpi
