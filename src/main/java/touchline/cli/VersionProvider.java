package touchline.cli;

import picocli.CommandLine;
import touchline.app.RuntimeReport;
import touchline.transport.UdpBackend;

/** {@code touchline --version}: the version from the build, the runtime, and the portable fallbacks in use. */
final class VersionProvider implements CommandLine.IVersionProvider {

    @Override
    public String[] getVersion() {
        RuntimeReport report = RuntimeReport.ofThisProcess(
                UdpBackend.onThisMachine(System.getProperty(UdpBackend.PROPERTY, UdpBackend.AUTO)));
        return report.lines().toArray(String[]::new);
    }
}
