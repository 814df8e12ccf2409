"""roslint (noetic 0.12.0) for a platform without it: the linters its CMake macros run.

``cpplint_wrapper`` and ``pycodestyle_wrapper`` run the linters Debian packages (``cpplint``,
``python3-pycodestyle``) with the ROS style guide's settings; ``test_wrapper`` turns a lint
run into a JUnit result for ``roslint_add_test``.
"""
