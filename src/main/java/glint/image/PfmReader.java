package glint.image;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;

/** Reads a colour Portable Float Map ("PF") into a frame buffer (rows top to bottom), every float as the file has it. */
public final class PfmReader {

    private PfmReader() {
    }

    public static FrameBuffer read(Path path) throws IOException {
        byte[] bytes = Files.readAllBytes(path);
        int[] pos = {0};
        String magic = token(bytes, pos);
        if (!magic.equals("PF")) {
            throw new IOException(path + ": not a colour PFM (magic '" + magic + "')");
        }
        int w = Integer.parseInt(token(bytes, pos));
        int h = Integer.parseInt(token(bytes, pos));
        double scale = Double.parseDouble(token(bytes, pos));
        pos[0]++; // the single whitespace after the scale
        ByteBuffer body = ByteBuffer.wrap(bytes, pos[0], bytes.length - pos[0])
                .order(scale < 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN);
        FrameBuffer frame = new FrameBuffer(w, h);
        float[] rgb = frame.rgb(); // the floats as they are in the file, an infinity or NaN too
        for (int y = h - 1; y >= 0; y--) {
            for (int i = 3 * y * w, end = i + 3 * w; i < end; i++) {
                rgb[i] = body.getFloat();
            }
        }
        return frame;
    }

    private static String token(byte[] bytes, int[] pos) {
        while (Character.isWhitespace(bytes[pos[0]])) {
            pos[0]++;
        }
        int start = pos[0];
        while (!Character.isWhitespace(bytes[pos[0]])) {
            pos[0]++;
        }
        return new String(bytes, start, pos[0] - start, java.nio.charset.StandardCharsets.US_ASCII);
    }
}
