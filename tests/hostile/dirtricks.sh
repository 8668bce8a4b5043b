#!/bin/sh
# Directory tricks (issue 21): usage: sh dirtricks.sh CLASS SECRET CORRECT_TRACE
# CLASS is the submissions directory; beside it are ../assignment.txt and
# ../outside/bob.trace (another class's correct trace). SECRET is a file
# in the teacher's home; CORRECT_TRACE a correct trace. Makes in CLASS:
#   zed.trace       -> ../outside/bob.trace   a link out of the directory (correct inside)
#   link-out.trace  -> ../outside/bob.trace   the same, graded before write-others.c spoils it
#   assign.trace    -> ../assignment.txt       a link to the assignment
#   hardlink.trace  a hard link to the assignment
#   secret.trace    -> SECRET                  a link into the teacher's home
#   passwd.csv      -> /etc/passwd             a link to a system file
#   devzero.trace   -> /dev/zero               a device (endless)
#   dangling.trace  -> ../nowhere.trace        a link to nothing
#   fifo.trace      a FIFO nobody writes
#   correct.txt     a correct trace with another extension
#   homework.py     a correct trace with an unknown extension
# Each must get a row with a verdict and a reason (none dropped), none may
# hang the grader, no link may be followed out of the directory (none of
# them passes: only correct.txt's right verdict is open), and nothing read
# through them (SWSECRET..., root:x:0:) may reach the gradebook.
set -u
class=$1 secret=$2 correct=$3
ln -s ../outside/bob.trace "$class/zed.trace"
ln -s ../outside/bob.trace "$class/link-out.trace"
ln -s ../assignment.txt "$class/assign.trace"
ln "$class/../assignment.txt" "$class/hardlink.trace"
ln -s "$secret" "$class/secret.trace"
ln -s /etc/passwd "$class/passwd.csv"
ln -s /dev/zero "$class/devzero.trace"
ln -s ../nowhere.trace "$class/dangling.trace"
mkfifo "$class/fifo.trace"
cp "$correct" "$class/correct.txt"
cp "$correct" "$class/homework.py"
