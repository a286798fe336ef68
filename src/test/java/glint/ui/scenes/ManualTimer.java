package glint.ui.scenes;

/** The scene watcher's timer in a test's hands: the watcher reads the file when the test says a period passed. */
final class ManualTimer implements SceneWatcher.Timer {

    private long periodMillis = -1;
    private Runnable read;
    private boolean closed;

    @Override
    public void every(long period, Runnable task) {
        this.periodMillis = period;
        this.read = task;
    }

    @Override
    public void close() {
        closed = true;
    }

    /** The period the watcher asked for, in ms; -1 before it started. */
    long periodMillis() {
        return periodMillis;
    }

    boolean closed() {
        return closed;
    }

    /** One period passed: the watcher reads the file, on the calling thread. */
    void tick() {
        if (read == null || closed) {
            throw new IllegalStateException("the watcher is not started, or closed");
        }
        read.run();
    }
}
