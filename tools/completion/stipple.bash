# SPDX-License-Identifier: MIT
# bash completion for stipple: subcommands, each subcommand's options, the
# values of options that take a word from a fixed set, and file names by
# extension for scenes, images and outputs.  Installed into
# share/bash-completion/completions/stipple; needs nothing from the
# bash-completion package.  tests/cli/test_completion.sh checks that the
# option lists equal what each subcommand's --help prints.

_stipple_commands="render animate dither scene compile bench help"

# the options every scene-rendering subcommand shares (tools/options.c)
_stipple_shared="--size --levels --dither --spacing --gamma --gamma-k --hidden --backface
 --no-shading --smooth --color --transparent --light --bright --ambient
 --attenuation --raw-power --parallel --fov --slices --stacks --shadows --raytrace --depth
 --min-weight --no-hierarchy --background --exposure --grey --edge-aa"

_stipple_options() {
    case $1 in
    render) echo "--output --scene-format --device --format --band --stats --palette --planes --outlines --crease-angle --outline-level --no-rescale --eye --at --up --invert --help $_stipple_shared" ;;
    animate) echo "--output --frames --orbit --elevation --hold --fps --stats --scene-format --eye --at --up --help $_stipple_shared" ;;
    compile) echo "--output --header --scene-format --static --spans --mesh --name --help $_stipple_shared" ;;
    dither) echo "--output --plain --dither --spacing --gamma --gamma-k --linear --palette --planes --size --resize --rotate --flip --invert --format --help" ;;
    scene) echo "--size --output --list --help" ;;
    bench) echo "--scenes --size --depth --min-weight --budget --help" ;;
    help) echo "--help" ;;
    esac
}

# Completes the current word with file names matching an extended glob
# (directories always offered, to walk into).
_stipple_files() {
    local IFS=$'\n' pattern=$1
    COMPREPLY=($(compgen -d -- "$cur"))
    COMPREPLY+=($(compgen -f -X "!$pattern" -- "$cur"))
}

_stipple() {
    local cur prev cmd
    cur=${COMP_WORDS[COMP_CWORD]}
    prev=${COMP_WORDS[COMP_CWORD - 1]}
    COMPREPLY=()
    if [ "$COMP_CWORD" -eq 1 ]; then
        COMPREPLY=($(compgen -W "$_stipple_commands --version --help" -- "$cur"))
        return
    fi
    cmd=${COMP_WORDS[1]}
    if [ "$cmd" = help ]; then
        [ "$COMP_CWORD" -eq 2 ] && COMPREPLY=($(compgen -W "$_stipple_commands" -- "$cur"))
        return
    fi
    # the value of the option before the cursor
    case $prev in
    --format)
        if [ "$cmd" = dither ]; then COMPREPLY=($(compgen -W "pbm plain-pbm png1 xbm c c-pages" -- "$cur"))
        else COMPREPLY=($(compgen -W "pbm plain-pbm pgm ppm png png1 txt xbm c c-pages" -- "$cur")); fi
        return ;;
    --resize) COMPREPLY=($(compgen -W "fit fill stretch" -- "$cur")); return ;;
    --rotate) COMPREPLY=($(compgen -W "90 180 270" -- "$cur")); return ;;
    --scene-format) COMPREPLY=($(compgen -W "nff obj off ply" -- "$cur")); return ;;
    --hidden) COMPREPLY=($(compgen -W "zbuffer painter none" -- "$cur")); return ;;
    -d | --dither) COMPREPLY=($(compgen -W "bayer2 bayer4 bayer8 bayer16 blue-noise clustered: clustered45: seed2x2 pattern2x2 user: fs fs:raster fs:blue atkinson sierra-lite jjn stucki burkes" -- "$cur")); return ;;
    --exposure) COMPREPLY=($(compgen -W "auto off" -- "$cur")); return ;;
    --spacing) COMPREPLY=($(compgen -W "linear exponential cubic" -- "$cur")); return ;;
    --palette)
        if [ "$cmd" = dither ]; then COMPREPLY=($(compgen -W "bw bwr grey4 grey16 rgb8" -- "$cur"))
        else COMPREPLY=($(compgen -W "grey pseudo bw bwr grey4 grey16 rgb8" -- "$cur")); fi
        COMPREPLY+=($(compgen -f -- "$cur")); return ;;
    --planes) COMPREPLY=($(compgen -f -- "$cur")); return ;;
    --outlines) COMPREPLY=($(compgen -W "silhouette crease both none" -- "$cur")); return ;;
    --outline-level) COMPREPLY=($(compgen -W "0 1 auto" -- "$cur")); return ;;
    --device) COMPREPLY=($(compgen -W "fb:/dev/fb0 usb spi:/dev/spidev0.0,controller=" -- "$cur")); return ;;
    -o | --output)
        case $cmd in
        compile) _stipple_files '*.c' ;;
        scene) _stipple_files '*.nff' ;;
        dither) _stipple_files '*.@(pbm|png|ppm|pgm|xbm|h)' ;;
        animate) _stipple_files '*.gif' ;;
        *) _stipple_files '*.@(pbm|pgm|ppm|png|txt|xbm|h)' ;;
        esac
        return ;;
    --header) _stipple_files '*.h'; return ;;
    --scenes) COMPREPLY=($(compgen -d -- "$cur")); return ;;
    -s | --size | -l | --levels | -g | --gamma | --gamma-k | --light | --bright | --ambient | \
        --attenuation | --fov | --slices | --stacks | --shadows | --depth | --min-weight | \
        -b | --band | --budget | --crease-angle | -n | --frames | --orbit | --elevation | --hold | \
        --fps | --eye | --at | --up)
        return ;; # a number: nothing to offer
    esac
    if [[ $cur == -* ]]; then
        COMPREPLY=($(compgen -W "$(_stipple_options "$cmd")" -- "$cur"))
        return
    fi
    case $cmd in
    render | compile | animate) _stipple_files '*.@(nff|obj|off|ply|NFF|OBJ|OFF|PLY)' ;;
    dither) _stipple_files '*.@(png|pgm|ppm|pbm|PNG|jpg|jpeg|JPG|JPEG)' ;;
    bench) _stipple_files '*.nff' ;;
    scene) COMPREPLY=($(compgen -W "$(stipple scene --list 2>/dev/null)" -- "$cur")) ;;
    esac
}

shopt -s extglob
complete -F _stipple stipple
