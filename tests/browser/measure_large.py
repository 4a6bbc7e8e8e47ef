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
    times.sort()
    median = times[len(times) // 2]
    print(f"  best {times[0]:.2f} s, median {median:.2f} s, worst {times[-1]:.2f} s over {runs} runs")
    return median


if __name__ == "__main__":
    median = main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 3)
    sys.exit(0 if median < 5.0 else f"slower than 5 s (median): {median:.2f} s")
