package glint.still;

/**
 * A still refused before any work, in words: an output that cannot or must not be written, an image the
 * heap or {@code ulimit -f} cannot hold. The command line says it as bad input ({@code glint: --output:
 * ...}, status 2), the window as {@code still not written: ...}.
 */
public final class StillRefused extends Exception {

    private final boolean output;

    /**
     * @param problem what is wrong and what to do, one line
     * @param output  whether it is the output file that is refused (the command line names its option)
     */
    StillRefused(String problem, boolean output) {
        super(problem, null, false, false);
        this.output = output;
    }

    /** What is wrong, one line: {@code cannot write 'out.png': Permission denied}. */
    public String problem() {
        return getMessage();
    }

    /** Whether the output file is what is refused (rather than the image's size). */
    public boolean aboutOutput() {
        return output;
    }
}
