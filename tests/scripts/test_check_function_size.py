"""scripts/check_function_size.py: finds bodies over the limit, and only those."""

import importlib.util
import os
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts",
                      "check_function_size.py")
spec = importlib.util.spec_from_file_location("check_function_size", SCRIPT)
check = importlib.util.module_from_spec(spec)
spec.loader.exec_module(check)


def body(lines):
    return "\n".join(f"  x += {k};" for k in range(lines))


class FunctionSizeTest(unittest.TestCase):
    def test_a_long_free_function_is_found_with_its_line_and_length(self):
        text = "namespace a {\nint f(int x) {\n" + body(10) + "\n}\n}  // namespace a\n"
        self.assertEqual(check.long_functions(text, 8), [(2, 11, "int f(int x) {")])
        self.assertEqual(check.long_functions(text, 11), [])

    def test_a_long_comment_exempts_it(self):
        text = "// long: one table, row by row\nint f(int x) {\n" + body(10) + "\n}\n"
        self.assertEqual(check.long_functions(text, 8), [])

    def test_inline_methods_and_initialiser_lists_count_but_control_blocks_do_not(self):
        text = ("class A {\n public:\n  A(int x)\n      : x_(x) {\n" + body(10) + "\n  }\n"
                "  int g() const {\n    if (x_) {\n" + body(10) + "\n    }\n    return 0;\n  }\n};\n")
        found = [line for line, _, _ in check.long_functions(text, 8)]
        self.assertEqual(found, [4, 16])

    def test_braces_in_strings_and_comments_do_not_count(self):
        text = ('void f() {\n  const char* s = "}}}";  // }\n  /* { */ char c = \'}\';\n' +
                body(10) + "\n}\n")
        self.assertEqual([n for _, n, _ in check.long_functions(text, 8)], [13])

    def test_a_lambda_counts_towards_its_function(self):
        text = "void f() {\n  auto g = [&](int y) {\n" + body(10) + "\n  };\n}\n"
        self.assertEqual([n for _, n, _ in check.long_functions(text, 8)], [13])


if __name__ == "__main__":
    unittest.main()
