package glint.app;

import glint.render.Tracer;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * Ctrl-C (SIGINT) or SIGTERM during a headless render: cancels the tracer at once, gives the main
 * thread a moment to stop and clean up, and deletes the image's temporary file, so that no partial
 * image is left and no stack trace is printed. Installed for the length of one run.
 */
final class Interrupts implements AutoCloseable {

    /** How long the JVM waits for the main thread to stop before it exits anyway. */
    static final long WAIT_MILLIS = 2000;

    private final Thread hook = new Thread(this::stop, "glint-interrupt");
    private final CountDownLatch finished = new CountDownLatch(1);
    private volatile Tracer tracer;
    private volatile Path temp;
    private volatile boolean stopping;
    private final java.util.concurrent.atomic.AtomicBoolean reported = new java.util.concurrent.atomic.AtomicBoolean();
    private final java.io.PrintWriter err;
    private final String message;

    private Interrupts(java.io.PrintWriter err, String message) {
        this.err = err;
        this.message = message;
    }

    /**
     * Installs the hook for one run.
     *
     * @param message what to print when stopped, by the main thread or, if it does not stop in
     *                time (a tile that takes long), by the hook
     */
    static Interrupts install(java.io.PrintWriter err, String message) {
        Interrupts interrupts = new Interrupts(err, message);
        Runtime.getRuntime().addShutdownHook(interrupts.hook);
        return interrupts;
    }

    /** The tracer to cancel and the temporary file to delete if the program is stopped. */
    void watch(Tracer renderer, Path temporaryFile) {
        this.tracer = renderer;
        this.temp = temporaryFile;
        if (stopping) {
            renderer.cancel();
        }
    }

    /** True once the program is being stopped. */
    boolean stopping() {
        return stopping;
    }

    /** What the shutdown hook does; also callable directly. */
    void stop() {
        stopping = true;
        Tracer t = tracer;
        if (t != null) {
            t.cancel();
        }
        try {
            finished.await(WAIT_MILLIS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        deleteTemp();
        report(message);
    }

    /** Prints the line saying the run was stopped, once, whoever comes first. */
    void report(String line) {
        if (reported.compareAndSet(false, true)) {
            err.println(line);
            err.flush();
        }
    }

    private void deleteTemp() {
        Path p = temp;
        if (p != null) {
            try {
                Files.deleteIfExists(p);
            } catch (IOException e) {
                // the JVM is exiting; nothing more can be done
            }
        }
    }

    /** The run is over: the hook is removed (or, if the JVM is already stopping, let go). */
    @Override
    public void close() {
        deleteTemp();
        finished.countDown();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // shutting down: the hook runs and returns at once
        }
    }
}
