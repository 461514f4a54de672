// Drives the whole board (collision_board_top) through its register bus as
// a host driver would, from a script the C++ test writes (commands.txt, one
// "op address data" a line, hex): 1 writes a word, 2 reads one and logs it
// to results.txt ("%08x"), 3 waits until the board stops (STATUS shows it
// not busy, or paused on an overflow), 0 ends. Six SSRAM banks, modelled
// behaviourally as pipelined ZBT parts (a read answers TILE_LATENCY cycles
// later, one access a cycle), hold the boxes of a tiled board.
module tb_board_top;
    parameter M = 2;
    parameter AW = 9;
    parameter FLOAT = 1;
    parameter WIDTH = 32;
    parameter COMPARE_LATENCY = 2;
    parameter FIFO_DEPTH = 16;
    parameter BUFFER_DEPTH = 64;
    parameter TILE_BOXES = 0;
    parameter TILE_LATENCY = 2;
    parameter MAX_WAIT = 4000000;   // cycles a wait may take

    reg clk = 0, reset = 1;
    reg [27:0] addr = 0;
    reg [31:0] wdata = 0;
    reg we = 0, re = 0;
    wire [31:0] rdata;
    wire rvalid, irq;
    wire [AW-1:0] ssram_addr;
    wire ssram_re;
    wire [5:0] ssram_we;
    wire [6*32-1:0] ssram_wdata;
    reg  [6*32-1:0] ssram_rdata;

    collision_board_top #(.M(M), .AW(AW), .FLOAT(FLOAT), .WIDTH(WIDTH), .COMPARE_LATENCY(COMPARE_LATENCY),
                          .FIFO_DEPTH(FIFO_DEPTH), .BUFFER_DEPTH(BUFFER_DEPTH), .TILE_BOXES(TILE_BOXES),
                          .TILE_LATENCY(TILE_LATENCY)) dut (
        .clk(clk), .reset(reset), .addr(addr), .wdata(wdata), .we(we), .re(re), .rdata(rdata), .rvalid(rvalid),
        .irq(irq), .ssram_addr(ssram_addr), .ssram_re(ssram_re), .ssram_we(ssram_we),
        .ssram_wdata(ssram_wdata), .ssram_rdata(ssram_rdata));

    always #5 clk = ~clk;

    // ---- SSRAM: bank b word i at banks[b * 2^AW + i] ----
    reg [31:0] banks [0:6*(1<<AW)-1];
    // answer[s]: the word read s cycles ago (answer[0]: read now).
    reg [6*32-1:0] answer [0:TILE_LATENCY];
    integer b, st;
    wire [6*32-1:0] read_now = {banks[5 * (1 << AW) + ssram_addr], banks[4 * (1 << AW) + ssram_addr],
                                banks[3 * (1 << AW) + ssram_addr], banks[2 * (1 << AW) + ssram_addr],
                                banks[1 * (1 << AW) + ssram_addr], banks[ssram_addr]};
    always @* ssram_rdata = TILE_LATENCY == 0 ? read_now : answer[TILE_LATENCY];
    always @(posedge clk) begin
        for (b = 0; b < 6; b = b + 1) if (ssram_we[b]) banks[b * (1 << AW) + ssram_addr] <= ssram_wdata[b*32 +: 32];
        answer[0] <= read_now;  // unused slot 0 keeps the shift uniform
        for (st = TILE_LATENCY; st >= 2; st = st - 1) answer[st] <= answer[st-1];
        if (TILE_LATENCY >= 1) answer[1] <= read_now;
        if (ssram_re && ssram_we != 0) $fatal(1, "SSRAM read and written in one cycle");
    end

    // ---- host bus ----
    task bus_write(input [27:0] a, input [31:0] d);
        begin
            @(negedge clk);
            addr = a; wdata = d; we = 1;
            @(negedge clk);
            we = 0;
        end
    endtask
    task bus_read(input [27:0] a, output [31:0] d);
        begin
            @(negedge clk);
            addr = a; re = 1;
            @(negedge clk);
            re = 0;
            if (!rvalid) $fatal(1, "no rvalid after a read");
            d = rdata;
        end
    endtask

    integer script, out, op, got, waited;
    reg [31:0] a, d, value;
    initial begin
        script = $fopen("commands.txt", "r");
        if (script == 0) $fatal(1, "commands.txt missing");
        out = $fopen("results.txt", "w");
        repeat (3) @(negedge clk);
        reset = 0;
        op = 1;
        while (op != 0) begin
            got = $fscanf(script, "%h %h %h\n", op, a, d);
            if (got != 3) op = 0;
            case (op)
                1: bus_write(a[27:0], d);
                2: begin
                    bus_read(a[27:0], value);
                    $fwrite(out, "%08x\n", value);
                end
                3: begin
                    waited = 0;
                    value = 1;
                    // Busy and not paused: the sweep runs.
                    while ((value & 5) == 1) begin
                        bus_read(28'h8, value);
                        waited = waited + 2;
                        if (waited > MAX_WAIT) $fatal(1, "the board never stopped");
                    end
                    if ((value & 7) != 0 && !irq) $fatal(1, "stopped without the interrupt");
                end
                default: ;
            endcase
        end
        $fclose(out);
        $finish;
    end
endmodule
