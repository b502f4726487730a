# SPDX-License-Identifier: MIT
# Points the repository's references to files that are not in it at the
# ones that are: the equations' restatement is docs/model.md (SPEC.md and
# DESIGN.md lived beside the checkout), and two test files moved to
# tests/core/.  Idempotent.  After merging branches that add such references,
# run (CTest stale_references fails until then):
#   tests/model/check_refs.sh . --fix

# the README's pointer becomes a link
s#(`\.\./shared/SPEC\.md`)#([docs/model.md](docs/model.md))#g
# the --raytrace help line keeps its width
s#ray-trace instead (SPEC\.md 5)#ray-trace (docs/model.md 5)#g
s#\.\./shared/SPEC\.md#docs/model.md#g
s#(`\.\./shared/DESIGN\.md`)#([docs/model.md](docs/model.md) section 7)#g
s#\.\./shared/DESIGN\.md#docs/model.md section 7#g
s#SPEC\.md#docs/model.md#g
s#tests/test_raster\.c#tests/core/test_raster.c#g
s#(tests/test_gamma\.c)#(tests/core/test_shade.c)#g
s#tests/test_gamma\.c#tests/core/test_shade.c#g
# a build machine's own folder in an example
s#=/work/shared/scenes/#=$PWD/tests/data/spd/#g
