# bash completion for shadelab: the commands, each command's options, the
# choices of an option's value (--shading gives none flat gouraud phong),
# and file names for meshes, outputs and scene files. Every word comes from
# the program's own --help, read as it is typed, so the completion says
# what the installed shadelab accepts.

# The commands: the Subcommands section of `shadelab --help`.
_shadelab_commands()
{
    "$1" --help 2>/dev/null | awk '
        /^Subcommands:/ { listing = 1; next }
        /^[^ ]/ { listing = 0 }
        listing && /^  [a-z]/ { print $1 }'
}

# The options of `shadelab COMMAND --help`, one a line: their names, comma
# separated, then the text of the value they take, if they take one. CLI11
# writes "  NAMES VALUE" padded to column 30 before the description, or
# alone on its line when longer; what follows the value (Excludes:, Needs:)
# is not part of it.
_shadelab_options()
{
    "$1" "$2" --help 2>/dev/null | awk '
        /^Options:/ { listing = 1; next }
        /^[^ ]/ { listing = 0 }
        listing && /^  -/ {
            head = length($0) > 30 && substr($0, 30, 1) == " " ? substr($0, 1, 30) : $0
            split(head, word, " ")
            value = word[2] ~ /^(Excludes|Needs):$/ || word[2] == "REQUIRED" ? "" : word[2]
            print word[1], value
        }'
}

_shadelab()
{
    local cur prev words cword split
    _init_completion -s || return

    local program=${words[0]} command="" i
    for ((i = 1; i < cword; i++)); do
        if [[ ${words[i]} != -* ]]; then
            command=${words[i]}
            break
        fi
    done
    if [[ -z $command ]]; then
        COMPREPLY=($(compgen -W "$(_shadelab_commands "$program") --help --version" -- "$cur"))
        return
    fi

    local options
    options=$(_shadelab_options "$program" "$command")
    if [[ $prev == -* ]]; then
        local value
        value=$(awk -v option="$prev" '
            { n = split($1, name, ","); for (i = 1; i <= n; i++) if (name[i] == option) { print $2; exit } }' \
            <<<"$options")
        if [[ -n $value ]]; then
            case $value in
                *'|'*)
                    # The words of a choice; placeholders (R,G,B, WxH) are not words to type.
                    COMPREPLY=($(compgen -W "$(tr '|' '\n' <<<"$value" | grep -v -e , -e '^[A-Z]*x\?[A-Z]*$')" -- "$cur"))
                    ;;
                DIR) _filedir -d ;;
                OUT | FILE* | CSV) _filedir ;;
            esac # other values are numbers, vectors and sizes: nothing to offer
            return
        fi
    fi
    if [[ $cur == -* ]]; then
        COMPREPLY=($(compgen -W "$(awk '{ gsub(",", " ", $1); print $1 }' <<<"$options")" -- "$cur"))
        return
    fi
    _filedir # a mesh (or a folder of them)
}
complete -F _shadelab shadelab
