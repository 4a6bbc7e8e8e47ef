# tests/browser/screenshot.py
# Screenshots pages written by `hmira view` in headless Chromium into small PNGs (256-colour
# palette) that carry the commands which made them in a tEXt chunk ("hmira-command").
#   python screenshot.py PAGE.html OUT.png "COMMANDS" [FRAGMENT]   (one or more quadruples)
import io
import sys

from PIL import Image, PngImagePlugin

import browser

SIZE = (720, 480)


def shoot(chromium, html, png, commands, fragment):
    opened = browser.open_page(chromium, html, fragment, size=SIZE, timeout_s=120)
    errors = [text for kind, text in opened.messages if kind == "error"]
    if errors:
        raise RuntimeError(f"{html}: the page logged errors: {errors}")
    opened.page.evaluate("document.querySelectorAll('.hmira-controls').forEach(e => e.style.display = 'none')")
    image = Image.open(io.BytesIO(opened.screenshot())).convert("RGB")
    opened.page.close()
    small = image.quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    info = PngImagePlugin.PngInfo()
    info.add_text("hmira-command", commands)
    info.add_text("Software", "hmira view + headless Chromium (scripts/gallery.sh)")
    small.save(png, optimize=True, pnginfo=info)
    return opened.seconds


def main(args):
    if len(args) % 4 != 0 or not args:
        sys.exit("usage: screenshot.py PAGE.html OUT.png COMMANDS FRAGMENT [...]")
    with browser.chromium() as chromium:
        for i in range(0, len(args), 4):
            seconds = shoot(chromium, *args[i:i + 4])
            print(f"  {args[i + 1]}: rendered in {seconds:.2f} s")


if __name__ == "__main__":
    main(sys.argv[1:])
