package touchline.app;

import java.io.IOException;
import java.io.InputStream;
import java.util.Properties;

/**
 * Touchline's version, as the build wrote it from pom.xml into {@code touchline/version.properties}
 * (Maven resource filtering). Shown by {@code touchline --version}, in the window's title and
 * Help → About, and it names the package ({@code touchline_<version>_amd64.deb}).
 *
 * @param version e.g. "0.5.0"; "unknown" when the classes were built without the resource
 */
public record ProductVersion(String version) {

    static final String RESOURCE = "/touchline/version.properties";

    /** The version of the classes running now. */
    public static ProductVersion ofThisBuild() {
        try (InputStream in = ProductVersion.class.getResourceAsStream(RESOURCE)) {
            return read(in);
        } catch (IOException e) {
            return new ProductVersion("unknown");
        }
    }

    /** Reads the properties file; "unknown" when missing or not filtered by the build. */
    static ProductVersion read(InputStream in) throws IOException {
        if (in == null) {
            return new ProductVersion("unknown");
        }
        Properties p = new Properties();
        p.load(in);
        String v = p.getProperty("version", "").trim();
        return new ProductVersion(v.isEmpty() || v.startsWith("${") ? "unknown" : v);
    }

    /** "Touchline 0.5.0". */
    public String title() {
        return "Touchline " + version;
    }
}
