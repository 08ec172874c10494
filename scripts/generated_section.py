"""The one writer of generated sections in docs (scripts/perf_sweeps.py, scripts/accuracy_report.py):
the text between a begin and an end marker is replaced by `body`; without the markers the section
is appended at the end. Hand-written text outside the markers is kept as it is."""
import re


def replace_section(text, begin, end, body):
    block = begin + "\n" + body + end
    pattern = re.compile(re.escape(begin) + ".*?" + re.escape(end), re.S)
    if pattern.search(text):
        return pattern.sub(lambda _: block, text)
    return text.rstrip("\n") + "\n\n" + block + "\n"
