# Sourced by the tests that run Windows programs under Wine: starts one Xvfb
# for the whole test (Wine's DXGI wants a display) and exports DISPLAY.
# -displayfd lets the server pick a free display, without the lock-file race
# of xvfb-run -a. Needs $work (a scratch folder); sets xvfb_pid, which the
# caller's exit trap kills.
exec 5>"$work/display"
Xvfb -displayfd 5 -screen 0 1024x768x24 -nolisten tcp >/dev/null 2>&1 &
xvfb_pid=$!
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || { echo "FAIL: Xvfb did not start"; exit 1; }
export DISPLAY=":$(head -1 "$work/display")"
