# tests/browser/measure_large.py
# Times a large page in headless Chromium: from navigation until window.hmiraRenderDone.
#   python measure_large.py PAGE.html [RUNS]     (run.sh --large makes the page and calls this)
import os
import sys

import browser


def main(html, runs=3):
    print(f"{html}: {os.path.getsize(html) / 2**20:.1f} MB")
    with browser.chromium() as chromium:
        times = []
        for _ in range(runs):
            opened = browser.open_page(chromium, html, timeout_s=120)
            errors = [t for k, t in opened.messages if k == "error"]
            if errors:
                sys.exit(f"{html}: the page logged errors: {errors}")
            timings = opened.page.evaluate("window.hmiraTimings")
            print(f"  navigation -> render-done {opened.seconds:.2f} s (script: decode+build {timings['build_ms'] / 1000:.2f} s,"
                  f" first frame at {timings['first_frame_ms'] / 1000:.2f} s)")
            times.append(opened.seconds)
            opened.page.close()
    print(f"  best {min(times):.2f} s, worst {max(times):.2f} s over {runs} runs")
    return max(times)


if __name__ == "__main__":
    worst = main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 3)
    sys.exit(0 if worst < 5.0 else f"slower than 5 s: {worst:.2f} s")
