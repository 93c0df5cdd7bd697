"""Fit configs, scenarios and truth files copied elsewhere: their relative paths made absolute
(and back to relative where a copy is written for users).

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


def top_level_path(path, key):
    """The absolute path a top-level `key:` of the YAML file `path` names; SystemExit when the
    file has none."""
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith(key + ":"):
                value = line.split(":", 1)[1].split("#", 1)[0].strip()
                return os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(path)),
                                                     value))
    raise SystemExit("%s: no `%s:` line" % (path, key))


def with_relative_paths(text, folder):
    """YAML text whose absolute top-level paths are made relative to `folder`, where the text
    is written."""
    out = []
    for line in text.splitlines(keepends=True):
        key = line.split(":", 1)[0]
        value = line.split(":", 1)[1].strip() if ":" in line else ""
        if key in TOP_LEVEL_PATHS and os.path.isabs(value):
            line = "%s: %s\n" % (key, os.path.relpath(value, os.path.abspath(folder)))
        out.append(line)
    return "".join(out)
