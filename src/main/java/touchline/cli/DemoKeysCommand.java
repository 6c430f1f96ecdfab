package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;
import touchline.transport.nao.CurveKeyFiles;
import touchline.transport.nao.NaoClientKeys;
import touchline.transport.nao.KeyFileException;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

/**
 * {@code touchline demo-keys DIR}: the demo's own CURVE key files for the simulated NAO and the
 * console ({@link CurveKeyFiles}), made once and kept; a broken set is made anew (it is the
 * demo's, no robot depends on it). The launcher's {@code ./touchline demo} calls it; hidden from
 * the help, since {@code touchline keys new} makes a team's real keys.
 */
@Command(name = "demo-keys", hidden = true, mixinStandardHelpOptions = true,
        description = "Make the demo's NAO key files in DIR unless they are there and readable.")
final class DemoKeysCommand implements Callable<Integer> {

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Parameters(index = "0", paramLabel = "DIR")
    Path dir;

    @Override
    public Integer call() {
        try {
            if (Files.exists(dir.resolve(NaoClientKeys.CONSOLE_SECRET))) {
                try {
                    NaoClientKeys.load(dir);
                    return 0;
                } catch (KeyFileException e) {
                    spec.commandLine().getErr().println(e.getMessage() + "; making new demo keys");
                }
            }
            new CurveKeyFiles().write(dir, true);
            spec.commandLine().getOut().println("demo NAO keys made in " + dir);
            return 0;
        } catch (IOException e) {
            spec.commandLine().getErr().println("cannot write the demo keys into " + dir + ": " + e.getMessage());
            return 1;
        }
    }
}
