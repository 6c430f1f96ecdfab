package touchline.bench;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

/** {@code bench nao}: the NAO link's budgets against a raw ZeroMQ echo, run against touchline-nao-sim. */
@Command(name = "nao", mixinStandardHelpOptions = true,
        description = "RPC round trip vs a raw ZeroMQ echo, short calls under load, camera fps, the cost of CURVE "
                + "(needs the robot side built).")
final class NaoBenchCommand implements Callable<Integer> {

    @Option(names = "--seconds", defaultValue = "4", description = "seconds per measurement (default ${DEFAULT-VALUE})")
    int seconds;

    @Option(names = "--curve-only", description = "measure only the cost of CURVE on the NAO link (NaoLink ping with and without)")
    boolean curveOnly;

    @Option(names = "--bin", description = "directory with touchline-nao-sim (default: robot-side/build/bin)")
    String bin;

    @Override
    public Integer call() throws Exception {
        List<String> args = new ArrayList<>(List.of("--seconds", Integer.toString(seconds)));
        if (bin != null) {
            args.addAll(List.of("--bin", bin));
        }
        if (curveOnly) {
            args.add("--curve-only");
        }
        return touchline.bench.nao.NaoBenchmark.run(args.toArray(String[]::new));
    }
}
