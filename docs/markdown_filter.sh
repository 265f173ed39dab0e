#!/bin/sh
# Doxygen's input filter for the Markdown pages (docs/CMakeLists.txt), for what GitHub renders but
# Doxygen would warn about: a link to a heading of the same page, [text](#heading-anchor), uses
# GitHub's anchor names, which Doxygen does not give its headings (Doxygen shows the text alone);
# and a page#heading written as plain text, which Doxygen takes for a link request (it is escaped).
# Lines are kept, so warnings still name the right line.
exec sed -E -e 's/\[([^]]*)\]\(#[^)]*\)/\1/g' -e 's/(^|[^]])([ (])([A-Za-z0-9_./-]+\.md)#/\1\2\3\\#/g' "$1"
