"""The manual's pages are doctests (``--doctest-glob=*.md``); Sphinx's configuration and its
build output are not."""
collect_ignore = ["conf.py"]
collect_ignore_glob = ["_build/*", "generated/*"]
