package glint.image;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Deletes temporary image files ({@link PartFile}) even when the program ends too abruptly to do it
 * itself: when the X server goes away, Xlib ends the JVM from native code (exit status 1), where no Java
 * code runs, not even a shutdown hook; SIGKILL and a crash end it the same way. The guard is a small
 * {@code /bin/sh} process that waits on a pipe from this JVM. The JVM's end, however it comes, closes the
 * pipe; the guard then deletes each of its files that is still there and, if it found one, says so in one
 * line on standard error. Closed after the files were renamed into place or deleted, it finds none and
 * says nothing. Where no such process can be started, files are left to the program's own clean-up.
 */
public final class PartGuard implements AutoCloseable {

    /**
     * Waits until the pipe from the JVM closes (the signals of a terminal or a process group are for the
     * program, which cleans up itself), then deletes what is left: {@code $0} is the line to say,
     * {@code $1 ...} the files.
     */
    private static final String SCRIPT = "trap '' INT HUP TERM QUIT\n"
            + "while read -r line; do :; done\n"
            + "left=\n"
            + "for f in \"$@\"; do if [ -e \"$f\" ]; then rm -f -- \"$f\"; left=1; fi; done\n"
            + "if [ -n \"$left\" ]; then printf '%s\\n' \"$0\" >&2; fi\n";

    private final Process process;

    private PartGuard(Process process) {
        this.process = process;
    }

    /**
     * Starts guarding {@code files}; {@code message} is the line the guard says if it has to delete any.
     * Never fails: without a guard process the files are the program's to delete.
     */
    public static PartGuard of(List<Path> files, String message) {
        List<String> command = new ArrayList<>(List.of("/bin/sh", "-c", SCRIPT, message));
        for (Path file : files) {
            command.add(file.toAbsolutePath().toString());
        }
        try {
            Process p = new ProcessBuilder(command).redirectOutput(ProcessBuilder.Redirect.DISCARD)
                    .redirectError(ProcessBuilder.Redirect.INHERIT).start();
            return new PartGuard(p);
        } catch (IOException | RuntimeException e) {
            return new PartGuard(null); // no shell, no processes left (ulimit -u): unguarded
        }
    }

    /** Whether a guard process is watching (tests). */
    boolean watching() {
        return process != null && process.isAlive();
    }

    /** The files are in place or deleted: the guard ends, finding nothing to do. */
    @Override
    public void close() {
        if (process == null) {
            return;
        }
        try (OutputStream pipe = process.getOutputStream()) {
            pipe.flush();
        } catch (IOException e) {
            // the guard has gone already
        }
    }
}
