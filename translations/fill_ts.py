#!/usr/bin/env python3
"""Fills translations/rigidlab_<lang>.ts from <lang>_strings.py and checks every translation.

Usage (from the repository root):
  /usr/lib/qt6/bin/lupdate -silent -no-obsolete -locations none ui app/rigidlab -ts translations/rigidlab_de.ts \
      -target-language de_DE
  python3 translations/fill_ts.py            # German (de)
  /usr/lib/qt6/bin/lupdate -silent -no-obsolete -pluralonly -locations none ui app/rigidlab -ts translations/rigidlab_en.ts \
      -target-language en
  python3 translations/fill_ts.py en         # English plural forms only
Messages without an entry in de_strings.py stay unfinished and are listed; the checks (placeholders, HTML tags,
accelerator count, plural forms) fail loudly instead of writing a broken file.
"""
import importlib
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
LANG = sys.argv[1] if len(sys.argv) > 1 else "de"
TS = os.path.join(HERE, f"rigidlab_{LANG}.ts")
sys.path.insert(0, HERE)
T = importlib.import_module(f"{LANG}_strings").T

PLACEHOLDER = re.compile(r"%L?\d+|%n")
TAG = re.compile(r"</?(?:b|i|u|br|p|a|span|tt|code|small|big|font|ul|ol|li|table|tr|td|h[1-6])\b[^>]*>")


def accelerators(text):
    return len(re.findall(r"&(?!&)", text.replace("&&", "")))


def check(ctx, src, forms, problems):
    for form in forms:
        if sorted(set(PLACEHOLDER.findall(src))) != sorted(set(PLACEHOLDER.findall(form))):
            problems.append(f"{ctx}: {src!r}: placeholders differ in {form!r}")
        if sorted(TAG.findall(src)) != sorted(TAG.findall(form)):
            problems.append(f"{ctx}: {src!r}: HTML tags differ in {form!r}")
        if accelerators(src) != accelerators(form):
            problems.append(f"{ctx}: {src!r}: accelerator count differs in {form!r}")
        if src.startswith(" ") != form.startswith(" ") or src.endswith(" ") != form.endswith(" "):
            problems.append(f"{ctx}: {src!r}: leading/trailing space differs in {form!r}")
        if "\n" in src and src.count("\n") != form.count("\n"):
            problems.append(f"{ctx}: {src!r}: line breaks differ in {form!r}")


def main():
    tree = ET.parse(TS)
    missing, problems, count = [], [], 0
    for context in tree.getroot().findall("context"):
        ctx = context.find("name").text
        for message in context.findall("message"):
            src = message.find("source").text or ""
            numerus = message.get("numerus") == "yes"
            translation = message.find("translation")
            if translation.get("type") in ("vanished", "obsolete"):
                continue
            count += 1
            entry = T.get(ctx, {}).get(src)
            if entry is None:
                missing.append(f"{ctx}: {src!r}")
                continue
            if numerus:
                if not isinstance(entry, list) or len(entry) != 2:
                    problems.append(f"{ctx}: {src!r}: plural message needs [singular, plural]")
                    continue
                check(ctx, src, entry, problems)
                for child in list(translation):
                    translation.remove(child)
                translation.text = None
                for form in entry:
                    ET.SubElement(translation, "numerusform").text = form
            else:
                if not isinstance(entry, str):
                    problems.append(f"{ctx}: {src!r}: not a plural message, needs one string")
                    continue
                check(ctx, src, [entry], problems)
                translation.text = entry
            translation.attrib.pop("type", None)
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    tree.write(TS, encoding="utf-8", xml_declaration=True)
    # lconvert writes the canonical Qt Linguist layout (DOCTYPE, indentation), so lupdate runs do not churn.
    lconvert = os.environ.get("LCONVERT", "/usr/lib/qt6/bin/lconvert")
    subprocess.run([lconvert, "-locations", "none", "-i", TS, "-o", TS], check=True)
    print(f"{count - len(missing)} of {count} messages translated")
    if missing:
        print("untranslated:\n" + "\n".join(missing))
    return 0


if __name__ == "__main__":
    sys.exit(main())
