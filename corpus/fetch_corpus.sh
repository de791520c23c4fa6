# The commands every corpus folder's fetch.sh offers, sourced by it after it has set HERE (its
# folder), REPOS ("owner/repo|commit|licence path|SPDX") and FILES ("owner/repo|path"):
#   fetch.sh [--verify]            verify every corpus file against the folder's SHA256SUMS
#   fetch.sh --list                print, per repository, the commit and the files it takes
#   fetch.sh --from-mirrors DIR    re-extract the files from bare git snapshots laid out as
#                                  DIR/<owner>+<repo>/repo, then verify the checksums
verify() { (cd "$HERE" && sha256sum -c --quiet SHA256SUMS) && echo "all $(wc -l < "$HERE/SHA256SUMS") files OK"; }

list() {
  for r in "${REPOS[@]}"; do
    IFS='|' read -r repo commit lic spdx <<<"$r"
    echo "github:$repo @ $commit  ($spdx, licence text from $lic)"
    for f in "${FILES[@]}"; do
      IFS='|' read -r frepo path <<<"$f"
      [[ "$frepo" == "$repo" ]] && echo "    $path"
    done
  done
}

from_mirrors() {
  local root="$1"
  for r in "${REPOS[@]}"; do
    IFS='|' read -r repo commit lic spdx <<<"$r"
    local gd="$root/${repo/\//+}/repo" dest="$HERE/${repo/\//__}"
    local head; head="$(git -C "$gd" rev-parse HEAD)"
    if [[ "$head" != "$commit" ]]; then
      echo "WARNING: $repo snapshot is at $head, corpus was taken at $commit" >&2
    fi
    mkdir -p "$dest"
    git -C "$gd" show "$commit:$lic" > "$dest/LICENSE"
    for f in "${FILES[@]}"; do
      IFS='|' read -r frepo path <<<"$f"
      [[ "$frepo" == "$repo" ]] || continue
      mkdir -p "$dest/$(dirname "$path")"
      git -C "$gd" show "$commit:$path" > "$dest/$path"
    done
  done
  verify
}

case "${1:-}" in
  ""|--verify) verify ;;
  --list) list ;;
  --from-mirrors) from_mirrors "${2:?usage: $0 --from-mirrors DIR}" ;;
  *) echo "usage: $0 [--verify|--list|--from-mirrors DIR]" >&2; exit 2 ;;
esac
