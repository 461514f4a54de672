"""Hooks of the docs site (mkdocs.yml): the README is the site's home page, and
a page of docs/ that the nav leaves out is a warning, so that `mkdocs build
--strict` fails on it as it fails on a broken link.

The README sits at the top of the repository and links into docs/; on the site
it sits beside the pages, so its `docs/` prefixes go, and the pages' links back
to `../README.md` point at the home page."""
import logging
import os
import re

from mkdocs.structure.files import File

log = logging.getLogger("mkdocs.hooks.cdvp")
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def on_files(files, config):
    files.append(File("README.md", root, config["site_dir"], config["use_directory_urls"]))
    return files


def on_nav(nav, config, files):
    in_nav = {page.file.src_path for page in nav.pages}
    for page in files.documentation_pages():
        if page.src_path not in in_nav:
            log.warning("docs/%s is not in the nav of mkdocs.yml", page.src_path)
    return nav


def on_page_markdown(markdown, page, config, files):
    if page.file.src_path == "README.md":
        return re.sub(r"\]\(docs/", "](", markdown)
    return re.sub(r"\]\(\.\./README\.md", "](README.md", markdown)
