"""Fit configs, scenarios and truth files copied elsewhere: their relative paths made absolute.

The scripts that derive a config or a scenario (a polish added, a motion changed) write the copy
into a scratch folder, where the original's relative paths (`scenario: ../x.yaml`, a truth
file's recordings) would no longer resolve.
"""
import os

TOP_LEVEL_PATHS = ("scenario", "robot", "data", "validation", "out")


def with_absolute_paths(path, append=None, drop_recordings=()):
    """The YAML text of `path` with its top-level paths and its recordings' `scenario:` paths
    made absolute, the recordings whose line names one of `drop_recordings` left out, and the
    lines of `append` (a dict key -> flow value) added at the end."""
    folder = os.path.dirname(os.path.abspath(path))
    out = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            key = line.split(":", 1)[0]
            if key in TOP_LEVEL_PATHS and not line.startswith((" ", "#")):
                value = line.split(":", 1)[1].split("#", 1)[0].strip()
                if value and not value.startswith("{"):
                    line = "%s: %s\n" % (key, os.path.normpath(os.path.join(folder, value)))
            if "scenario: ../" in line and line.lstrip().startswith("- {"):
                if any(name in line for name in drop_recordings):
                    continue
                start = line.index("scenario: ") + len("scenario: ")
                end = line.index("}", start)
                target = os.path.normpath(os.path.join(folder, line[start:end].strip()))
                line = line[:start] + target + line[end:]
            out.append(line)
    for key, value in (append or {}).items():
        out.append("%s: %s\n" % (key, value))
    return "".join(out)
