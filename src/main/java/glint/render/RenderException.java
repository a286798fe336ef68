package glint.render;

/** A frame could not be rendered (a worker failed). */
public final class RenderException extends RuntimeException {

    public RenderException(String message, Throwable cause) {
        super(message, cause);
    }
}
