# Sourced by the end-to-end tests (lib.sh does). Tests wait for a condition,
# never for a number of frames or a sleep: a loaded machine is slow, not
# wrong. A limit only stops a hung program, so limits are generous
# (wall-clock seconds, at least SW_E2E_WAIT, default 30).
# wait_until SECONDS COMMAND...: run COMMAND every 0.1 s until it succeeds
# (0), or 1 when SECONDS have passed.
wait_until() {
    limit=$1; shift
    [ "$limit" -ge "${SW_E2E_WAIT:-30}" ] || limit=${SW_E2E_WAIT:-30}
    end=$(( $(date +%s) + limit ))
    until "$@"; do
        [ "$(date +%s)" -lt "$end" ] || return 1
        sleep 0.1
    done
}
