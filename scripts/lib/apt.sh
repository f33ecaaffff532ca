# Sourced by the scripts that call apt-get. psi_apt runs apt-get one at a time: .ci/run prepares
# the other Debian systems (debian-system.sh installs debootstrap) while setup-deps.sh installs
# this Debian's packages, and two apt-get at once fail on dpkg's lock. Our own calls queue on a
# lock file; apt-get also waits up to 15 minutes for a lock held by anything else (an
# unattended upgrade on a machine just booted).
#   psi_apt [SUDO] ARGS...     e.g. psi_apt "$SUDO" install -y foo
psi_apt() {
  local sudo=$1
  shift
  local queue=()
  command -v flock >/dev/null && queue=(flock /var/cache/apt/psivolume-apt.lock)
  $sudo "${queue[@]}" apt-get -o DPkg::Lock::Timeout=900 "$@"
}
